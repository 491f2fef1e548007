// Status: the outcome of a core operation, as a value (no exceptions).
//
// A Status is either OK or carries a code and a human-readable message that
// names what was wrong (for dataset errors: "file:line: what"). Every code
// but kIOError has the meaning of the canonical gRPC code of the same name;
// kIOError (a file that exists could not be read or written) has no gRPC
// twin. The server maps them in one place per transport (gRPC:
// common/status_mapping.cc; HTTP: server/http/api_error.cc); the core
// itself never includes gRPC.
//
// [[nodiscard]]: every function returning a Status must have it handled.
//
// Thread-safety: a Status is an immutable value; copies are independent.

#ifndef LOCATOR_STATUS_H_
#define LOCATOR_STATUS_H_

#include <string>
#include <string_view>
#include <utility>

namespace locator {

class [[nodiscard]] Status {
 public:
  enum class Code {
    kOk = 0,
    kInvalidArgument,
    kNotFound,
    kFailedPrecondition,
    kResourceExhausted,
    kUnavailable,
    kInternal,
    kIOError,
    // Codes of the serving layer; the core never returns them.
    kCancelled,
    kDeadlineExceeded,
    kUnauthenticated,
    kPermissionDenied,
    kUnimplemented,
  };

  // An OK status.
  Status() = default;

  static Status OK() { return Status(); }
  static Status InvalidArgument(std::string_view msg) {
    return Status(Code::kInvalidArgument, msg);
  }
  static Status NotFound(std::string_view msg) {
    return Status(Code::kNotFound, msg);
  }
  static Status FailedPrecondition(std::string_view msg) {
    return Status(Code::kFailedPrecondition, msg);
  }
  static Status ResourceExhausted(std::string_view msg) {
    return Status(Code::kResourceExhausted, msg);
  }
  static Status Unavailable(std::string_view msg) {
    return Status(Code::kUnavailable, msg);
  }
  static Status Internal(std::string_view msg) {
    return Status(Code::kInternal, msg);
  }
  static Status IOError(std::string_view msg) {
    return Status(Code::kIOError, msg);
  }
  static Status Cancelled(std::string_view msg) {
    return Status(Code::kCancelled, msg);
  }
  static Status DeadlineExceeded(std::string_view msg) {
    return Status(Code::kDeadlineExceeded, msg);
  }
  static Status Unauthenticated(std::string_view msg) {
    return Status(Code::kUnauthenticated, msg);
  }
  static Status PermissionDenied(std::string_view msg) {
    return Status(Code::kPermissionDenied, msg);
  }
  static Status Unimplemented(std::string_view msg) {
    return Status(Code::kUnimplemented, msg);
  }

  bool ok() const { return code_ == Code::kOk; }
  Code code() const { return code_; }
  // The message without the code prefix; empty for OK.
  const std::string& message() const { return message_; }
  // This status's code with `message` instead of its own (OK stays OK).
  Status WithMessage(std::string_view message) const {
    return ok() ? Status() : Status(code_, message);
  }
  // "OK" or "<CodeName>: <message>", for logs and CLI output.
  std::string ToString() const;

 private:
  Status(Code code, std::string_view msg) : code_(code), message_(msg) {}

  Code code_ = Code::kOk;
  std::string message_;
};

// Returns the canonical upper-case name of `code` ("INVALID_ARGUMENT", ...).
std::string_view StatusCodeName(Status::Code code);

}  // namespace locator

#endif  // LOCATOR_STATUS_H_
