// ServerProcess: a server binary (locatord, locator-noop-server) run as a
// child process by end-to-end tests.
//
// Spawn() starts the binary with fork/exec, its stdout on a pipe and its
// stderr in a temporary file; the child is killed if the test process dies.
// WaitForListening() reads stdout up to the
// "<program> listening on HOST:PORT" line; WaitUntilServing() then polls the
// gRPC health service until locator.v1.Locator reports SERVING, over a
// channel with the credentials of a client the server accepts (set by
// Start(), or set_client_security()). Start() does all three. The destructor
// sends SIGTERM to a child that is still running and reaps it (SIGKILL if it
// has not exited after kExitGrace).
//
// Owns the child, the stdout pipe and the stderr file. Thread-safety: none;
// one test thread drives it (the accessors may be read from any thread once
// the server is listening).

#ifndef LOCATOR_TESTS_TESTING_SERVER_PROCESS_H_
#define LOCATOR_TESTS_TESTING_SERVER_PROCESS_H_

#include <sys/types.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "client/health_check.h"
#include "common/channel_options.h"
#include "locator/status.h"

namespace locator::test {

class ServerProcess {
 public:
  static constexpr std::chrono::seconds kStartTimeout{60};
  static constexpr std::chrono::seconds kExitGrace{20};

  // Spawns `binary` with `args` (not including argv[0]). IOError if it
  // cannot be forked; a binary that cannot be executed exits 127.
  static Status Spawn(const std::string& binary,
                      const std::vector<std::string>& args,
                      std::unique_ptr<ServerProcess>* process);
  // Spawn() + WaitForListening() + WaitUntilServing(), probing health with
  // `client_security`.
  static Status Start(const std::string& binary,
                      const std::vector<std::string>& args,
                      std::unique_ptr<ServerProcess>* process,
                      const ChannelSecurity& client_security = {});

  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  // Reads stdout until the listening line. Unavailable, with the child's
  // stderr, if the child closes stdout first or `timeout` passes.
  Status WaitForListening(std::chrono::milliseconds timeout = kStartTimeout);
  // Polls health until SERVING. Unavailable, with stderr, if the child
  // exits or `timeout` passes first.
  Status WaitUntilServing(std::chrono::milliseconds timeout = kStartTimeout);
  // One health probe of locator.v1.Locator (a 1 s deadline).
  grpc::Status CheckHealth(HealthStatus* status) const;

  // The credentials of a client the server accepts (TLS, token).
  const ChannelSecurity& client_security() const { return client_security_; }
  void set_client_security(const ChannelSecurity& security) {
    client_security_ = security;
  }

  pid_t pid() const { return pid_; }
  // Valid after WaitForListening().
  int port() const { return port_; }
  // "HOST:PORT" from the listening line, for grpc::CreateChannel.
  const std::string& target() const { return target_; }

  // Sends `signal_number` to the child (nothing once it has been reaped).
  void SendSignal(int signal_number);
  // Waits up to `timeout` for the child to exit and returns its exit code
  // (128 + N if signal N killed it), or nullopt on timeout.
  std::optional<int> WaitForExit(std::chrono::milliseconds timeout);
  // Everything the child has written to stderr so far.
  std::string StderrText() const;
  // Polls stderr until it contains `text` or `timeout` passes; returns
  // StderrText() either way (for the caller's assertion and message).
  std::string WaitForStderr(const std::string& text,
                            std::chrono::milliseconds timeout) const;

 private:
  ServerProcess() = default;
  Status Failure(const std::string& what) const;

  pid_t pid_ = -1;
  std::optional<int> exit_code_;  // set once reaped
  int stdout_fd_ = -1;
  std::string stdout_text_;
  std::string stderr_path_;
  int port_ = 0;
  std::string target_;
  ChannelSecurity client_security_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_TESTING_SERVER_PROCESS_H_
