// HealthChecker: a client of the standard grpc.health.v1.Health/Check RPC
// that needs no generated code.
//
// Debian's gRPC ships no client stubs for the health service, and generating
// our own copy of grpc/health/v1/health.proto would register that file in
// protobuf's global descriptor pool, where it clashes with any other copy
// linked into the same process. The two messages are one field each, so they
// are encoded by hand over a generic stub instead.
//
// Owns a generic stub on a shared channel. Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_HEALTH_CHECK_H_
#define LOCATOR_CLIENT_HEALTH_CHECK_H_

#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>

#include <memory>
#include <string>
#include <string_view>

namespace locator {

// grpc.health.v1.HealthCheckResponse.ServingStatus, same numbers.
enum class HealthStatus {
  kUnknown = 0,
  kServing = 1,
  kNotServing = 2,
  kServiceUnknown = 3,
};

// "SERVING", "NOT_SERVING", ... as the proto spells them.
std::string_view HealthStatusName(HealthStatus status);

// The wire form of HealthCheckRequest{service}.
std::string EncodeHealthCheckRequest(std::string_view service);
// Reads HealthCheckResponse{status} from its wire form; false if malformed.
bool DecodeHealthCheckResponse(std::string_view wire, HealthStatus* status);

class HealthChecker {
 public:
  explicit HealthChecker(std::shared_ptr<grpc::Channel> channel);

  // Calls Check(service) with `context` (whose deadline the caller sets);
  // "" asks about the server as a whole.
  grpc::Status Check(grpc::ClientContext* context, std::string_view service,
                     HealthStatus* status);

 private:
  grpc::GenericStub stub_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_HEALTH_CHECK_H_
