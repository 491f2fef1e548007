// DrainGate: admits calls until the server starts draining, and tells when
// the calls it admitted have all ended.
//
// gRPC's own Server::Shutdown() refuses new calls too, but not cleanly: a
// call that reaches a connection before the server's GOAWAY does is
// cancelled (CANCELLED, grpc/grpc#41785), and Shutdown() keeps doing that
// for as long as in-flight calls take to drain. So locatord drains in two
// steps: Close() the gate (handlers answer new calls UNAVAILABLE "server is
// shutting down" while gRPC keeps accepting them), WaitUntilIdle() for the
// admitted calls, and only then Shutdown(), with nothing left in flight.
//
// A call is in flight while any copy of its Ticket lives; whatever finishes
// the call holds one (the handler's frame, a batch's shared state, a stream
// reactor).
//
// Thread-safety: all methods may be called concurrently.

#ifndef LOCATOR_SERVER_DRAIN_GATE_H_
#define LOCATOR_SERVER_DRAIN_GATE_H_

#include <atomic>
#include <chrono>
#include <memory>

namespace locator {

class DrainGate {
 public:
  // Held while a call runs; null when the call was refused.
  using Ticket = std::shared_ptr<const void>;

  // A ticket for a new call, or null once Close() has been called.
  Ticket Enter();

  // Refuses every later Enter().
  void Close();

  // Waits until no ticket is left or `deadline` passes; true if none is.
  bool WaitUntilIdle(std::chrono::system_clock::time_point deadline) const;

 private:
  std::atomic<bool> closed_{false};
  // Shared with the tickets, which may outlive the gate at process exit.
  std::shared_ptr<std::atomic<int>> in_flight_ =
      std::make_shared<std::atomic<int>>(0);
};

}  // namespace locator

#endif  // LOCATOR_SERVER_DRAIN_GATE_H_
