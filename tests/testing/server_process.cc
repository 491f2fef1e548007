#include "tests/testing/server_process.h"

#include <fcntl.h>
#include <grpcpp/grpcpp.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace locator::test {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::string_view kListeningOn = " listening on ";
constexpr auto kPollInterval = std::chrono::milliseconds(20);

std::string ErrnoText(const std::string& what) {
  return what + ": " + std::strerror(errno);
}

int RemainingMs(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline - Clock::now());
  return left.count() > 0 ? static_cast<int>(left.count()) : 0;
}

// Parses "<program> listening on HOST:PORT".
bool ParseListeningLine(std::string_view line, std::string* target, int* port) {
  const size_t at = line.find(kListeningOn);
  if (at == std::string_view::npos) return false;
  const std::string_view address = line.substr(at + kListeningOn.size());
  const size_t colon = address.rfind(':');
  if (colon == std::string_view::npos) return false;
  *port = std::atoi(std::string(address.substr(colon + 1)).c_str());
  *target = std::string(address);
  return *port > 0;
}

}  // namespace

Status ServerProcess::Spawn(const std::string& binary,
                            const std::vector<std::string>& args,
                            std::unique_ptr<ServerProcess>* process) {
  std::unique_ptr<ServerProcess> child(new ServerProcess());
  const char* tmpdir = std::getenv("TMPDIR");
  std::string stderr_template =
      std::string(tmpdir != nullptr ? tmpdir : "/tmp") +
      "/locator-server-XXXXXX";
  const int stderr_fd = mkostemp(stderr_template.data(), O_CLOEXEC);
  if (stderr_fd < 0) return Status::IOError(ErrnoText("mkostemp"));
  child->stderr_path_ = stderr_template;
  int stdout_pipe[2];
  if (pipe2(stdout_pipe, O_CLOEXEC) != 0) {
    close(stderr_fd);
    return Status::IOError(ErrnoText("pipe2"));
  }
  child->stdout_fd_ = stdout_pipe[0];

  // Everything the child needs is prepared before fork(): between fork()
  // and exec() only async-signal-safe calls are allowed.
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(binary.c_str()));
  for (const std::string& arg : args) {
    argv.push_back(const_cast<char*>(arg.c_str()));
  }
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    // A test that dies without running destructors must not leave its
    // server running: the kernel kills the child when the parent exits.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    dup2(stdout_pipe[1], STDOUT_FILENO);
    dup2(stderr_fd, STDERR_FILENO);
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  close(stdout_pipe[1]);
  close(stderr_fd);
  if (pid < 0) return Status::IOError(ErrnoText("fork"));
  child->pid_ = pid;
  *process = std::move(child);
  return Status::OK();
}

Status ServerProcess::Start(const std::string& binary,
                            const std::vector<std::string>& args,
                            std::unique_ptr<ServerProcess>* process,
                            const ChannelSecurity& client_security) {
  std::unique_ptr<ServerProcess> child;
  Status status = Spawn(binary, args, &child);
  if (status.ok()) child->set_client_security(client_security);
  if (status.ok()) status = child->WaitForListening();
  if (status.ok()) status = child->WaitUntilServing();
  if (status.ok()) *process = std::move(child);
  return status;
}

ServerProcess::~ServerProcess() {
  if (pid_ > 0 && !exit_code_) {
    SendSignal(SIGTERM);
    if (!WaitForExit(kExitGrace)) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  if (stdout_fd_ >= 0) close(stdout_fd_);
  if (!stderr_path_.empty()) unlink(stderr_path_.c_str());
}

Status ServerProcess::WaitForListening(std::chrono::milliseconds timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  for (;;) {
    size_t line_end;
    while ((line_end = stdout_text_.find('\n')) != std::string::npos) {
      const std::string line = stdout_text_.substr(0, line_end);
      stdout_text_.erase(0, line_end + 1);
      if (ParseListeningLine(line, &target_, &port_)) return Status::OK();
    }
    pollfd readable{stdout_fd_, POLLIN, 0};
    const int ready = poll(&readable, 1, RemainingMs(deadline));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return Failure("printed no listening line in time");
    char chunk[4096];
    const ssize_t got = read(stdout_fd_, chunk, sizeof(chunk));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      WaitForExit(std::chrono::seconds(5));  // for the exit code in the message
      return Failure("closed stdout before listening");
    }
    stdout_text_.append(chunk, static_cast<size_t>(got));
  }
}

grpc::Status ServerProcess::CheckHealth(HealthStatus* status) const {
  HealthChecker checker(
      CreateLocatorChannel({.target = target_, .security = client_security_}));
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() +
                       std::chrono::seconds(1));
  return checker.Check(&context, "locator.v1.Locator", status);
}

Status ServerProcess::WaitUntilServing(std::chrono::milliseconds timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  for (;;) {
    HealthStatus health = HealthStatus::kUnknown;
    if (CheckHealth(&health).ok() && health == HealthStatus::kServing) {
      return Status::OK();
    }
    if (WaitForExit(std::chrono::milliseconds(0))) {
      return Failure("exited before serving");
    }
    if (Clock::now() >= deadline) return Failure("not SERVING in time");
    std::this_thread::sleep_for(kPollInterval);
  }
}

void ServerProcess::SendSignal(int signal_number) {
  if (pid_ > 0 && !exit_code_) kill(pid_, signal_number);
}

std::optional<int> ServerProcess::WaitForExit(
    std::chrono::milliseconds timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  while (!exit_code_ && pid_ > 0) {
    int wait_status = 0;
    const pid_t reaped = waitpid(pid_, &wait_status, WNOHANG);
    if (reaped == pid_) {
      exit_code_ = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status)
                                          : 128 + WTERMSIG(wait_status);
    } else if (Clock::now() >= deadline) {
      break;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  return exit_code_;
}

std::string ServerProcess::StderrText() const {
  std::ifstream file(stderr_path_);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string ServerProcess::WaitForStderr(
    const std::string& text, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::string seen = StderrText();
  while (seen.find(text) == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    seen = StderrText();
  }
  return seen;
}

Status ServerProcess::Failure(const std::string& what) const {
  std::ostringstream message;
  message << "server (pid " << pid_ << ") " << what;
  if (exit_code_) message << "; exit code " << *exit_code_;
  message << "; stderr:\n" << StderrText();
  return Status::Unavailable(message.str());
}

}  // namespace locator::test
