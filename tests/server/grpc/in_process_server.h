// InProcessServer: a gRPC server inside the test process, serving one
// service, and a Locator stub on an in-process channel to it, so that tests
// drive the serving layer through real gRPC calls without a child process
// or a port.
//
// Owns the server; the service must outlive it. Thread-safety: stub() may
// be used from any thread; Shutdown() waits for the calls in flight.

#ifndef LOCATOR_TESTS_SERVER_IN_PROCESS_SERVER_H_
#define LOCATOR_TESTS_SERVER_IN_PROCESS_SERVER_H_

#include <grpcpp/grpcpp.h>

#include <memory>

#include "locator/v1/locator.grpc.pb.h"

namespace locator::test {

class InProcessServer {
 public:
  // Starts serving `service` (not owned).
  explicit InProcessServer(grpc::Service* service);
  ~InProcessServer() { Shutdown(); }
  InProcessServer(const InProcessServer&) = delete;
  InProcessServer& operator=(const InProcessServer&) = delete;

  // A stub on a new in-process channel.
  std::unique_ptr<v1::Locator::Stub> NewStub() const;
  // Stops the server once the calls in flight have finished.
  void Shutdown();

 private:
  std::unique_ptr<grpc::Server> server_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_IN_PROCESS_SERVER_H_
