// GrpcCodeName: the canonical upper-case name of a gRPC status code, as the
// server's metrics label calls and the clients print failed ones.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_COMMON_GRPC_CODE_NAME_H_
#define LOCATOR_COMMON_GRPC_CODE_NAME_H_

#include <grpcpp/support/status.h>

#include <string_view>

namespace locator {

// The canonical upper-case name of `code` ("UNAVAILABLE", ...); "UNKNOWN"
// for a value outside the canonical codes.
std::string_view GrpcCodeName(grpc::StatusCode code);

}  // namespace locator

#endif  // LOCATOR_COMMON_GRPC_CODE_NAME_H_
