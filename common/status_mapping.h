// The one place where a Status becomes a gRPC status, for the server's
// handlers and the clients' own refusals alike (HTTP's is
// server/http/api_error.h).
//
// Every RPC that fails goes through ToGrpcStatus, so a client sees the same
// code for the same cause whichever RPC it used. The
// message is passed through unchanged (core messages already name what was
// wrong: the coordinate, the point index, the file and line), unless it is
// longer than kMaxStatusMessageBytes: gRPC sends it in a header, and one that
// overflows the client's header limit arrives as an unrelated error. Messages
// quote client text short (common/input_text.h), so only a bug or an
// unforeseen echo ever reaches the cut.

#ifndef LOCATOR_COMMON_STATUS_MAPPING_H_
#define LOCATOR_COMMON_STATUS_MAPPING_H_

#include <grpcpp/support/status.h>

#include "locator/status.h"

namespace locator {

// Maps `status` to the gRPC status with the same meaning and message (cut to
// kMaxStatusMessageBytes): every code to its namesake, IOError to INTERNAL.
grpc::Status ToGrpcStatus(const Status& status);

}  // namespace locator

#endif  // LOCATOR_COMMON_STATUS_MAPPING_H_
