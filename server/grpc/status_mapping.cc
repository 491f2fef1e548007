#include "server/grpc/status_mapping.h"

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
  }
  return grpc::StatusCode::UNKNOWN;
}

grpc::StatusCode ToGrpcCode(Refusal refusal) {
  switch (refusal) {
    case Refusal::kUnauthenticated:
      return grpc::StatusCode::UNAUTHENTICATED;
    case Refusal::kPermissionDenied:
      return grpc::StatusCode::PERMISSION_DENIED;
    case Refusal::kShuttingDown:
      // The call never started: a client may retry it on another replica.
      return grpc::StatusCode::UNAVAILABLE;
  }
  return grpc::StatusCode::UNKNOWN;
}

}  // namespace

grpc::Status ToGrpcStatus(const Status& status) {
  return ToGrpcStatus(status, status.message());
}

grpc::Status ToGrpcStatus(const Status& status, std::string_view message) {
  if (status.ok()) return grpc::Status::OK;
  return grpc::Status(ToGrpcCode(status.code()),
                      TruncatedMessage(message, kMaxStatusMessageBytes));
}

grpc::Status ToGrpcStatus(Refusal refusal, const std::string& message) {
  return grpc::Status(ToGrpcCode(refusal),
                      TruncatedMessage(message, kMaxStatusMessageBytes));
}

unsigned HttpStatusFor(grpc::StatusCode code) {
  switch (code) {
    case grpc::StatusCode::OK:
      return 200;
    case grpc::StatusCode::INVALID_ARGUMENT:
    case grpc::StatusCode::FAILED_PRECONDITION:
    case grpc::StatusCode::OUT_OF_RANGE:
      return 400;
    case grpc::StatusCode::UNAUTHENTICATED:
      return 401;
    case grpc::StatusCode::PERMISSION_DENIED:
      return 403;
    case grpc::StatusCode::NOT_FOUND:
      return 404;
    case grpc::StatusCode::ALREADY_EXISTS:
    case grpc::StatusCode::ABORTED:
      return 409;
    case grpc::StatusCode::RESOURCE_EXHAUSTED:
      return 429;
    case grpc::StatusCode::CANCELLED:
      return 499;  // nginx's "client closed request", as grpc-gateway
    case grpc::StatusCode::UNIMPLEMENTED:
      return 501;
    case grpc::StatusCode::UNAVAILABLE:
      return 503;
    case grpc::StatusCode::DEADLINE_EXCEEDED:
      return 504;
    default:
      return 500;
  }
}

}  // namespace locator
