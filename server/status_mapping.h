// The one place where a core Status becomes a gRPC status.
//
// Every RPC that fails because the core said so goes through ToGrpcStatus, so
// a client sees the same code for the same cause whichever RPC it used. The
// message is passed through unchanged: core messages already name what was
// wrong (the coordinate, the point index, the file and line).

#ifndef LOCATOR_SERVER_STATUS_MAPPING_H_
#define LOCATOR_SERVER_STATUS_MAPPING_H_

#include <grpcpp/support/status.h>

#include "server/core/status.h"

namespace locator {

// Maps `status` to the gRPC status with the same meaning and message:
// InvalidArgument, NotFound, FailedPrecondition, ResourceExhausted and
// Unavailable to their namesakes; Internal and IOError to INTERNAL.
grpc::Status ToGrpcStatus(const Status& status);

}  // namespace locator

#endif  // LOCATOR_SERVER_STATUS_MAPPING_H_
