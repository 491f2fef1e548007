#include "server/http/api_error.h"

#include <array>
#include <cstdint>
#include <string_view>

#include "common/input_text.h"
#include "common/json_writer.h"

namespace locator {
namespace {

// How each canonical code shows over HTTP, indexed by its number.
struct CanonicalCodeInfo {
  std::string_view name;
  unsigned http_status;
};
constexpr std::array<CanonicalCodeInfo, 17> kCanonicalCodes = {{
    {"OK", 200},
    // nginx's "client closed request", as grpc-gateway.
    {"CANCELLED", 499},
    {"UNKNOWN", 500},
    {"INVALID_ARGUMENT", 400},
    {"DEADLINE_EXCEEDED", 504},
    {"NOT_FOUND", 404},
    {"ALREADY_EXISTS", 409},
    {"PERMISSION_DENIED", 403},
    {"RESOURCE_EXHAUSTED", 429},
    {"FAILED_PRECONDITION", 400},
    {"ABORTED", 409},
    {"OUT_OF_RANGE", 400},
    {"UNIMPLEMENTED", 501},
    {"INTERNAL", 500},
    {"UNAVAILABLE", 503},
    {"DATA_LOSS", 500},
    {"UNAUTHENTICATED", 401},
}};
constexpr int kUnknown = 2;

const CanonicalCodeInfo& InfoOf(int canonical) {
  const bool known =
      canonical >= 0 && canonical < static_cast<int>(kCanonicalCodes.size());
  return kCanonicalCodes[known ? canonical : kUnknown];
}

}  // namespace

int CanonicalCode(Status::Code code) {
  switch (code) {
    case Status::Code::kOk:
      return 0;
    case Status::Code::kCancelled:
      return 1;
    case Status::Code::kInvalidArgument:
      return 3;
    case Status::Code::kDeadlineExceeded:
      return 4;
    case Status::Code::kNotFound:
      return 5;
    case Status::Code::kPermissionDenied:
      return 7;
    case Status::Code::kResourceExhausted:
      return 8;
    case Status::Code::kFailedPrecondition:
      return 9;
    case Status::Code::kUnimplemented:
      return 12;
    case Status::Code::kInternal:
    case Status::Code::kIOError:
      return 13;
    case Status::Code::kUnavailable:
      return 14;
    case Status::Code::kUnauthenticated:
      return 16;
  }
  return kUnknown;
}

unsigned HttpStatusForCanonicalCode(int canonical) {
  return InfoOf(canonical).http_status;
}

unsigned HttpStatusFor(Status::Code code) {
  return HttpStatusForCanonicalCode(CanonicalCode(code));
}

HttpResponse ApiError(const Status& status, unsigned http_status) {
  HttpResponse response =
      ApiError(CanonicalCode(status.code()), status.message());
  if (http_status != 0) response.status = http_status;
  return response;
}

HttpResponse ApiError(int canonical, std::string_view message) {
  const CanonicalCodeInfo& info = InfoOf(canonical);
  JsonWriter json;
  json.BeginObject()
      .Key("code")
      .Integer(static_cast<uint64_t>(canonical))
      .Key("status")
      .String(info.name)
      .Key("message")
      .String(TruncatedMessage(message, kMaxStatusMessageBytes))
      .EndObject();
  return HttpResponse{.status = info.http_status,
                      .content_type = kJsonContentType,
                      .body = json.text()};
}

HttpResponse OpenTopoDataError(const Status& status) {
  unsigned http_status = HttpStatusFor(status.code());
  std::string_view name = "SERVER_ERROR";
  switch (status.code()) {
    case Status::Code::kInvalidArgument:
    case Status::Code::kFailedPrecondition:
    case Status::Code::kNotFound:
    case Status::Code::kResourceExhausted:
      http_status = 400;
      name = "INVALID_REQUEST";
      break;
    case Status::Code::kUnauthenticated:
    case Status::Code::kPermissionDenied:
      name = "REQUEST_DENIED";
      break;
    default:
      break;
  }
  JsonWriter json;
  json.BeginObject()
      .Key("error")
      .String(TruncatedMessage(status.message(), kMaxStatusMessageBytes))
      .Key("status")
      .String(name)
      .EndObject();
  HttpResponse answer{.status = http_status,
                      .content_type = kJsonContentType,
                      .body = json.text()};
  if (status.code() == Status::Code::kUnavailable) {
    answer.headers.emplace_back("Retry-After",
                                std::to_string(kRetryAfterSeconds));
  }
  return answer;
}

HttpResponse BusyError(const std::string& message) {
  HttpResponse answer = ApiError(Status::Unavailable(message), 503);
  answer.headers.emplace_back("Retry-After",
                              std::to_string(kRetryAfterSeconds));
  return answer;
}

}  // namespace locator
