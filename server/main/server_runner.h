// ServerRunner: a started gRPC server plus the Boost.Asio loop that runs the
// process around it (signals, periodic work, shutdown).
//
// Start() builds the server with the default health service and
// reflection, TLS and the connection limits of the config's
// TransportConfig, marks it NOT_SERVING, starts it and prints "<program>
// listening on HOST:PORT" (the port actually bound) on stdout. A port in
// use by another server fails (gRPC's default SO_REUSEPORT is off, so two
// servers never share a port's connections). Run() then
// drives the loop on the calling thread until SIGINT or SIGTERM, or until
// Stop(): the server goes NOT_SERVING, the OnDrain() hooks run (the
// services refuse new calls and wait for theirs to end), gRPC shuts down,
// in-flight calls get what is left of kDrainDeadline to complete, the
// BeforeExit() hook runs, and Run() returns the exit code for main() to end
// the process with. SIGHUP never ends the loop: it calls the OnHangup()
// handler (e.g. a reload), or is logged and ignored without one.
//
// Owns the server, the io_context, its signal sets and timers.
// Thread-safety: SetServing() may be called from any thread; RunEvery() and
// Stop() only on the loop thread (post to io_context() from elsewhere); the
// rest from the thread that called Start().

#ifndef LOCATOR_SERVER_SERVER_RUNNER_H_
#define LOCATOR_SERVER_SERVER_RUNNER_H_

#include <grpcpp/grpcpp.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"
#include "server/config/server_config.h"

namespace locator {

class ServerRunner {
 public:
  static constexpr std::chrono::seconds kDrainDeadline{10};

  // Starts `services` on config's address as described above, with
  // `interceptors` seeing every call, into *runner. Unavailable "cannot
  // listen on ADDRESS: ..." if the address cannot be bound (in use, by
  // another server too).
  static Status Start(
      std::string_view program, const ServingConfig& config,
      const std::vector<grpc::Service*>& services,
      std::vector<std::unique_ptr<
          grpc::experimental::ServerInterceptorFactoryInterface>>
          interceptors,
      std::unique_ptr<ServerRunner>* runner);

  // The methods a server Start()ed with the protobuf services named
  // `services` (e.g. "locator.v1.Locator") answers, as
  // "/package.Service/Method": theirs, and those of the health and
  // reflection services Start() adds. A name that is not a generated
  // service linked into the program adds none.
  static std::vector<std::string> MethodsServed(
      const std::vector<std::string_view>& services);

  ServerRunner(const ServerRunner&) = delete;
  ServerRunner& operator=(const ServerRunner&) = delete;

  boost::asio::io_context& io_context() { return io_context_; }

  // Reports SERVING or NOT_SERVING for the whole server ("") and for
  // locator.v1.Locator.
  void SetServing(bool serving);

  // Calls `hook` on the loop thread when the drain starts, before gRPC's
  // shutdown, with the drain's deadline; it may block until then.
  using DrainHook =
      std::function<void(std::chrono::system_clock::time_point deadline)>;
  void OnDrain(DrainHook hook);

  // Calls `tick` on the loop thread every `seconds` until the loop stops.
  void RunEvery(double seconds, std::function<void()> tick);

  // Shuts the server down (draining in-flight calls) and makes Run() return
  // `exit_code`.
  void Stop(int exit_code);

  // Calls `handler` on the loop thread on every SIGHUP.
  void OnHangup(std::function<void()> handler);
  // Calls `hook` on the loop thread once the server has shut down, right
  // before Run() returns (after a signal or Stop()).
  void BeforeExit(std::function<void()> hook);

  // Runs the loop until a signal (exit code 0) or Stop(), runs the
  // BeforeExit() hook and returns the exit code. Every call has been
  // answered by then, so main() may end the process at once (std::_Exit)
  // rather than tear the rest down: gRPC's global shutdown can idle for up
  // to 10 s on an executor thread's poll, and a triangulation build cannot
  // be interrupted.
  int Run();

 private:
  explicit ServerRunner(std::string_view program);

  void ScheduleTick(boost::asio::steady_timer* timer,
                    std::chrono::steady_clock::duration period,
                    std::function<void()> tick);
  // Waits for the next SIGHUP, handles it and waits again.
  void WaitForHangup();

  const std::string program_;
  boost::asio::io_context io_context_;
  boost::asio::signal_set signals_;
  // SIGHUP, registered from the start so that it cannot kill the process.
  boost::asio::signal_set hangup_;
  std::function<void()> hangup_handler_;
  std::function<void()> before_exit_;
  std::list<boost::asio::steady_timer> timers_;  // stable addresses
  std::vector<DrainHook> drain_hooks_;
  std::unique_ptr<grpc::Server> server_;
  int exit_code_ = 0;
};

// Ends the process with `exit_code` once ServerRunner::Run() has returned
// it: the log streams are flushed, and nothing still alive is torn down
// (see Run() for why).
[[noreturn]] void ExitWithoutTeardown(int exit_code);

}  // namespace locator

#endif  // LOCATOR_SERVER_SERVER_RUNNER_H_
