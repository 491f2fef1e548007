#include "tests/server/http/devtools_page.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "common/status_macros.h"
#include "tests/server/http/browser.h"

extern char** environ;

namespace locator::test {
namespace {

// `text` as a JSON string.
std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

bool Has(const JsonValue& object, const char* name) {
  return std::holds_alternative<JsonObject>(object.value) &&
         object.object().count(name) > 0;
}

}  // namespace

Status DevToolsPage::Open(const std::string& url, bool accept_dialogs,
                          std::unique_ptr<DevToolsPage>* page) {
  std::unique_ptr<DevToolsPage> opened(new DevToolsPage());
  opened->accept_dialogs_ = accept_dialogs;
  std::string dir = ::testing::TempDir() + "devtools-XXXXXX";
  if (mkdtemp(dir.data()) == nullptr) return Status::IOError("mkdtemp");
  opened->profile_dir_ = dir;
  int commands[2], events[2];
  if (pipe2(commands, O_CLOEXEC) != 0 || pipe2(events, O_CLOEXEC) != 0) {
    return Status::IOError("pipe");
  }
  // The browser reads commands on fd 3 and writes on fd 4.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, commands[0], 3);
  posix_spawn_file_actions_adddup2(&actions, events[1], 4);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  const std::string stderr_path = dir + "/stderr.txt";
  posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {kChromium,
                                   "--headless",
                                   "--no-sandbox",
                                   "--disable-gpu",
                                   "--window-size=1280,800",
                                   "--disable-quic",
                                   "--no-first-run",
                                   "--disable-background-networking",
                                   "--disable-component-update",
                                   "--disable-sync",
                                   "--remote-debugging-pipe",
                                   "--user-data-dir=" + dir + "/profile",
                                   "about:blank"};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const int spawned = posix_spawn(&opened->pid_, kChromium, &actions, nullptr,
                                  argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(commands[0]);
  close(events[1]);
  opened->to_browser_ = commands[1];
  opened->from_browser_ = events[0];
  if (spawned != 0) {
    opened->pid_ = -1;
    return Status::IOError("cannot run " + std::string(kChromium));
  }

  JsonValue target, attached, ignored;
  Status status = opened->Call("Target.createTarget",
                               R"({"url": "about:blank"})", true, &target);
  if (status.ok()) {
    status = opened->Call("Target.attachToTarget",
                          R"({"flatten": true, "targetId": )" +
                              Quoted(target["targetId"].string()) + "}",
                          true, &attached);
  }
  if (status.ok()) {
    opened->session_ = attached["sessionId"].string();
    status = opened->Call("Page.enable", "{}", false, &ignored);
  }
  if (status.ok()) {
    status = opened->Call("Page.navigate", R"({"url": )" + Quoted(url) + "}",
                          false, &ignored);
  }
  if (!status.ok()) return status;
  *page = std::move(opened);
  return Status::OK();
}

DevToolsPage::~DevToolsPage() {
  if (pid_ > 0) {
    const std::string close_browser = R"({"id": 0, "method": "Browser.close"})";
    (void)!write(to_browser_, close_browser.c_str(), close_browser.size() + 1);
    // Up to 10 s for it to go, then it is killed.
    int status = 0;
    pid_t reaped = 0;
    for (int i = 0; i < 100 && reaped == 0; ++i) {
      reaped = waitpid(pid_, &status, WNOHANG);
      if (reaped == 0) poll(nullptr, 0, 100);
    }
    if (reaped == 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
    }
  }
  if (to_browser_ >= 0) close(to_browser_);
  if (from_browser_ >= 0) close(from_browser_);
  if (!profile_dir_.empty()) {
    std::error_code ignored;
    std::filesystem::remove_all(profile_dir_, ignored);
  }
}

Status DevToolsPage::WaitForValue(const std::string& expression,
                                  std::string* value) {
  const auto deadline = std::chrono::steady_clock::now() + kTimeout;
  for (;;) {
    JsonValue result;
    // Fails while the page is between documents; asked again then.
    if (Call("Runtime.evaluate",
             R"({"returnByValue": true, "expression": )" + Quoted(expression) +
                 "}",
             false, &result)
            .ok() &&
        Has(result, "result") && Has(result["result"], "value") &&
        std::holds_alternative<std::string>(result["result"]["value"].value)) {
      *value = result["result"]["value"].string();
      if (!value->empty()) return Status::OK();
    }
    if (std::chrono::steady_clock::now() > deadline) {
      return Status::Unavailable("the page never gave a value for " +
                                 expression);
    }
    // Between evaluations, wait for (and answer) what the page sends.
    JsonValue message;
    const Status read = ReadMessage(
        std::chrono::steady_clock::now() + std::chrono::milliseconds(50),
        &message);
    if (read.ok() && Has(message, "id")) {
      answers_[static_cast<int>(message["id"].number())] = message;
    }
  }
}

namespace {

// The bytes of the base64 text `text` (RFC 4648, padded, as DevTools
// sends binary data); InvalidArgument at the first byte outside it.
Status DecodeBase64(const std::string& text, std::string* bytes) {
  constexpr std::string_view kDigits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  bytes->clear();
  uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    const size_t digit = kDigits.find(c);
    if (digit == std::string_view::npos) {
      return Status::InvalidArgument("not base64");
    }
    bits = bits << 6 | static_cast<uint32_t>(digit);
    count += 6;
    if (count >= 8) {
      count -= 8;
      bytes->push_back(static_cast<char>(bits >> count & 0xff));
    }
  }
  return Status::OK();
}

}  // namespace

Status DevToolsPage::CaptureScreenshot(std::string* png) {
  JsonValue result;
  RETURN_IF_ERROR(
      Call("Page.captureScreenshot", R"({"format": "png"})", false, &result));
  if (!Has(result, "data")) {
    return Status::Internal("Page.captureScreenshot answered no data");
  }
  return DecodeBase64(result["data"].string(), png);
}

Status DevToolsPage::Call(const std::string& method, const std::string& params,
                          bool to_browser, JsonValue* result) {
  const int id = next_id_++;
  std::string command = "{\"id\": " + std::to_string(id) +
                        ", \"method\": " + Quoted(method) +
                        ", \"params\": " + params;
  if (!to_browser) command += ", \"sessionId\": " + Quoted(session_);
  command += "}";
  if (write(to_browser_, command.c_str(), command.size() + 1) !=
      static_cast<ssize_t>(command.size() + 1)) {
    return Status::IOError("cannot write to Chromium");
  }
  JsonValue answer;
  if (Status status = AwaitAnswer(id, &answer); !status.ok()) return status;
  if (Has(answer, "error")) {
    return Status::Internal(method + ": " +
                            answer["error"]["message"].string());
  }
  *result = answer["result"];
  return Status::OK();
}

Status DevToolsPage::AwaitAnswer(int id, JsonValue* answer) {
  const auto deadline = std::chrono::steady_clock::now() + kTimeout;
  for (;;) {
    if (const auto found = answers_.find(id); found != answers_.end()) {
      *answer = std::move(found->second);
      answers_.erase(found);
      return Status::OK();
    }
    JsonValue message;
    if (Status status = ReadMessage(deadline, &message); !status.ok()) {
      return status;
    }
    if (Has(message, "id")) {
      answers_[static_cast<int>(message["id"].number())] = message;
    } else if (Has(message, "method") &&
               message["method"].string() == "Page.javascriptDialogOpening") {
      dialogs_.push_back(message["params"]["message"].string());
      JsonValue ignored;
      if (Status status = Call("Page.handleJavaScriptDialog",
                               std::string(R"({"accept": )") +
                                   (accept_dialogs_ ? "true" : "false") + "}",
                               false, &ignored);
          !status.ok()) {
        return status;
      }
    }
  }
}

Status DevToolsPage::ReadMessage(std::chrono::steady_clock::time_point deadline,
                                 JsonValue* message) {
  for (;;) {
    if (const size_t end = received_.find('\0'); end != std::string::npos) {
      const std::string text = received_.substr(0, end);
      received_.erase(0, end + 1);
      return ParseJson(text, message);
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return Status::Unavailable("no message");
    pollfd readable{.fd = from_browser_, .events = POLLIN, .revents = 0};
    if (poll(&readable, 1, static_cast<int>(left.count())) <= 0) continue;
    char chunk[65536];
    const ssize_t got = read(from_browser_, chunk, sizeof(chunk));
    if (got <= 0) {
      return Status::IOError("Chromium closed the pipe; its stderr:\n" +
                             ReadFileBytes(profile_dir_ + "/stderr.txt"));
    }
    received_.append(chunk, static_cast<size_t>(got));
  }
}

}  // namespace locator::test
