// DevToolsPage: one page in headless Chromium driven over the DevTools
// protocol on a pipe (--remote-debugging-pipe: commands on the browser's fd
// 3, answers and events on its fd 4, each a JSON text ended by a NUL), for
// the browser tests that --dump-dom cannot do: a page that opens a
// JavaScript dialog (confirm()) blocks there for ever in headless Chromium,
// unless a DevTools client answers it. Each dialog the page opens is
// answered as Open() was told, and its message kept.
//
// Owns the Chromium process (killed, if it does not close, and reaped by
// the destructor) and its fresh profile directory. Thread-safety: none; one
// test thread.

#ifndef LOCATOR_TESTS_SERVER_HTTP_DEVTOOLS_PAGE_H_
#define LOCATOR_TESTS_SERVER_HTTP_DEVTOOLS_PAGE_H_

#include <sys/types.h>

#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "locator/status.h"
#include "tests/server/http/json_value.h"

namespace locator::test {

class DevToolsPage {
 public:
  // How long a command, or WaitForValue(), may take.
  static constexpr std::chrono::seconds kTimeout{60};

  // Starts Chromium and opens `url` in a new tab; every JavaScript dialog
  // of the page is accepted if `accept_dialogs`, dismissed otherwise.
  static Status Open(const std::string& url, bool accept_dialogs,
                     std::unique_ptr<DevToolsPage>* page);
  ~DevToolsPage();

  DevToolsPage(const DevToolsPage&) = delete;
  DevToolsPage& operator=(const DevToolsPage&) = delete;

  // Evaluates the JavaScript `expression` in the page until it yields a
  // non-empty string, into *value; Unavailable after kTimeout.
  Status WaitForValue(const std::string& expression, std::string* value);

  // The page as it is drawn now, a PNG of the viewport of the 1280 x 800
  // window, into *png (Page.captureScreenshot).
  Status CaptureScreenshot(std::string* png);
  // The messages of the dialogs the page opened, in order.
  const std::vector<std::string>& dialogs() const { return dialogs_; }

 private:
  DevToolsPage() = default;

  // Sends `method` with `params` (a JSON object), to the page's session
  // unless `to_browser`, and waits for its result (the error as Internal).
  Status Call(const std::string& method, const std::string& params,
              bool to_browser, JsonValue* result);
  // Reads messages until answer `id` has come, answering dialogs meanwhile.
  Status AwaitAnswer(int id, JsonValue* answer);
  // Reads one message, waiting at most until `deadline`.
  Status ReadMessage(std::chrono::steady_clock::time_point deadline,
                     JsonValue* message);

  pid_t pid_ = -1;
  int to_browser_ = -1;
  int from_browser_ = -1;
  std::string profile_dir_;
  std::string received_;  // bytes read, not yet a whole message
  int next_id_ = 1;
  std::string session_;
  bool accept_dialogs_ = false;
  std::vector<std::string> dialogs_;
  std::map<int, JsonValue> answers_;  // arrived while waiting for another
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_DEVTOOLS_PAGE_H_
