// The one place where a core Status, or the service's refusal of a call,
// becomes a gRPC status, and a gRPC status an HTTP one.
//
// Every RPC that fails because the core said so goes through ToGrpcStatus, so
// a client sees the same code for the same cause whichever RPC it used. The
// message is passed through unchanged (core messages already name what was
// wrong: the coordinate, the point index, the file and line), unless it is
// longer than kMaxStatusMessageBytes: gRPC sends it in a header, and one that
// overflows the client's header limit arrives as an unrelated error. Messages
// quote client text short (common/input_text.h), so only a bug or an
// unforeseen echo ever reaches the cut.

#ifndef LOCATOR_SERVER_STATUS_MAPPING_H_
#define LOCATOR_SERVER_STATUS_MAPPING_H_

#include <grpcpp/support/status.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "locator/status.h"

namespace locator {

// The longest status message sent, in bytes; longer ones end in "...". Even
// percent-encoded (3 bytes for each byte that is not printable ASCII) it
// fits gRPC's default 8 KiB header limit with room for the other headers.
inline constexpr size_t kMaxStatusMessageBytes = 1024;

// Maps `status` to the gRPC status with the same meaning and message (cut to
// kMaxStatusMessageBytes): InvalidArgument, NotFound, FailedPrecondition,
// ResourceExhausted and Unavailable to their namesakes; Internal and IOError
// to INTERNAL.
grpc::Status ToGrpcStatus(const Status& status);
// The same with `message` instead of status's own (OK stays OK).
grpc::Status ToGrpcStatus(const Status& status, std::string_view message);

// Why the service refuses a call before doing any of its work.
enum class Refusal {
  kUnauthenticated,   // no well-formed credentials: UNAUTHENTICATED
  kPermissionDenied,  // credentials this RPC does not accept:
                      // PERMISSION_DENIED
  kShuttingDown,      // the server is draining: UNAVAILABLE
};

// The gRPC status for `refusal`, with `message` (cut likewise).
grpc::Status ToGrpcStatus(Refusal refusal, const std::string& message);

// The HTTP status the HTTP/JSON API answers a call that ended with `code`,
// as grpc-gateway maps them: OK 200, INVALID_ARGUMENT, FAILED_PRECONDITION
// and OUT_OF_RANGE 400, UNAUTHENTICATED 401, PERMISSION_DENIED 403,
// NOT_FOUND 404, ALREADY_EXISTS and ABORTED 409, RESOURCE_EXHAUSTED 429,
// CANCELLED 499, UNIMPLEMENTED 501, UNAVAILABLE 503, DEADLINE_EXCEEDED 504,
// the rest 500.
unsigned HttpStatusFor(grpc::StatusCode code);

}  // namespace locator

#endif  // LOCATOR_SERVER_STATUS_MAPPING_H_
