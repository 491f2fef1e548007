#include "common/status_mapping.h"

#include "common/input_text.h"

namespace locator {
namespace {

grpc::StatusCode ToGrpcCode(Status::Code code) {
  switch (code) {
    case Status::Code::kOk:
      return grpc::StatusCode::OK;
    case Status::Code::kInvalidArgument:
      return grpc::StatusCode::INVALID_ARGUMENT;
    case Status::Code::kNotFound:
      return grpc::StatusCode::NOT_FOUND;
    case Status::Code::kFailedPrecondition:
      return grpc::StatusCode::FAILED_PRECONDITION;
    case Status::Code::kResourceExhausted:
      return grpc::StatusCode::RESOURCE_EXHAUSTED;
    case Status::Code::kUnavailable:
      return grpc::StatusCode::UNAVAILABLE;
    case Status::Code::kInternal:
      return grpc::StatusCode::INTERNAL;
    case Status::Code::kIOError:
      // The core reads datasets (at startup and on Reload) and reads and
      // writes tuning state files; a missing file is kNotFound, not this.
      // A file that exists but cannot be read or written (permissions, a
      // directory, a full disk) is the server's own failure, and retrying
      // against the same server would not help: UNAVAILABLE would invite
      // exactly that retry, so report INTERNAL.
      return grpc::StatusCode::INTERNAL;
    case Status::Code::kCancelled:
      return grpc::StatusCode::CANCELLED;
    case Status::Code::kDeadlineExceeded:
      return grpc::StatusCode::DEADLINE_EXCEEDED;
    case Status::Code::kUnauthenticated:
      return grpc::StatusCode::UNAUTHENTICATED;
    case Status::Code::kPermissionDenied:
      return grpc::StatusCode::PERMISSION_DENIED;
    case Status::Code::kUnimplemented:
      return grpc::StatusCode::UNIMPLEMENTED;
  }
  return grpc::StatusCode::UNKNOWN;
}

}  // namespace

grpc::Status ToGrpcStatus(const Status& status) {
  if (status.ok()) return grpc::Status::OK;
  return grpc::Status(
      ToGrpcCode(status.code()),
      TruncatedMessage(status.message(), kMaxStatusMessageBytes));
}

}  // namespace locator
