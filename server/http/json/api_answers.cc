#include "server/http/json/api_answers.h"

#include <string>

#include "common/input_text.h"
#include "common/proto_json.h"
#include "server/http/api_error.h"

namespace locator {

HttpResponse JsonAnswer(const google::protobuf::Message& message) {
  return HttpResponse{.content_type = kJsonContentType,
                      .body = ProtoJson(message)};
}

HttpResponse NoRoute(const HttpRequest& request) {
  return ApiError(Status::NotFound(
      "no API method " + QuotedInput(request.method + " " + request.path) +
      " (GET /v1/datasets, POST /v1/datasets/{name}:locate, :locateBatch, "
      ":profile or :grid, GET /v1/datasets/{name}/tiles.json or "
      "/v1/datasets/{name}/tiles/{z}/{x}/{y}.png)"));
}

HttpResponse MethodNotAllowed(const HttpRequest& request,
                              std::string_view allowed) {
  HttpResponse response = ApiError(
      Status::Unimplemented(QuotedInput(request.method) +
                            " is not allowed on " + QuotedInput(request.path) +
                            "; use " + std::string(allowed)),
      405);
  response.headers.emplace_back("Allow", std::string(allowed));
  return response;
}

}  // namespace locator
