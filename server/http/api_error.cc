#include "server/http/api_error.h"

#include "common/grpc_code_name.h"
#include "common/input_text.h"
#include "common/json_writer.h"
#include "server/grpc/status_mapping.h"

namespace locator {

HttpResponse ApiError(const grpc::Status& status, unsigned http_status) {
  JsonWriter json;
  json.BeginObject()
      .Key("code")
      .Integer(static_cast<uint64_t>(status.error_code()))
      .Key("status")
      .String(GrpcCodeName(status.error_code()))
      .Key("message")
      .String(TruncatedMessage(status.error_message(), kMaxStatusMessageBytes))
      .EndObject();
  return HttpResponse{.status = http_status != 0
                                    ? http_status
                                    : HttpStatusFor(status.error_code()),
                      .content_type = kJsonContentType,
                      .body = json.text()};
}

HttpResponse BusyError(const std::string& message) {
  HttpResponse answer =
      ApiError(grpc::Status(grpc::StatusCode::UNAVAILABLE, message), 503);
  answer.headers.emplace_back("Retry-After",
                              std::to_string(kRetryAfterSeconds));
  return answer;
}

}  // namespace locator
