#include "server/http/json/api_answers.h"

#include <google/protobuf/util/json_util.h>

#include <string>

#include "common/input_text.h"
#include "common/proto_json.h"
#include "server/http/api_error.h"

namespace locator {
namespace {

// The most of protobuf's complaint about a body that an error shows: room
// for the field's path and a quoted prefix of the value.
constexpr size_t kParseErrorBytes = 2 * kQuotedInputBytes;

}  // namespace

Status ParseJsonMessage(std::string_view body, google::protobuf::Message* out) {
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = false;
  if (body.empty()) body = "{}";
  if (const auto parsed =
          google::protobuf::util::JsonStringToMessage(body, out, options);
      !parsed.ok()) {
    // Protobuf adds a picture of the position on further lines, and quotes
    // an unknown field or a bad value whole.
    const std::string_view error(parsed.message().data(),
                                 parsed.message().size());
    return Status::InvalidArgument(
        "the body is not a " + out->GetTypeName() + " in JSON: " +
        TruncatedMessage(error.substr(0, error.find('\n')), kParseErrorBytes));
  }
  return Status::OK();
}

HttpResponse JsonAnswer(const google::protobuf::Message& message) {
  return HttpResponse{.content_type = kJsonContentType,
                      .body = ProtoJson(message)};
}

HttpResponse NoRoute(const HttpRequest& request) {
  return ApiError(Status::NotFound(
      "no API method " + QuotedInput(request.method + " " + request.path) +
      " (GET /v1/datasets, POST /v1/datasets/{name}:locate, :locateBatch, "
      ":profile or :grid, GET /v1/datasets/{name}/tiles.json, "
      "tiles/z/x/y.png or quantized-mesh/(layer.json|z/x/y.terrain))"));
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

bool NamesETag(std::string_view header, std::string_view etag) {
  while (!header.empty()) {
    const size_t comma = header.find(',');
    std::string_view tag = header.substr(0, comma);
    while (!tag.empty() && (tag.front() == ' ' || tag.front() == '\t')) {
      tag.remove_prefix(1);
    }
    while (!tag.empty() && (tag.back() == ' ' || tag.back() == '\t')) {
      tag.remove_suffix(1);
    }
    if (tag.starts_with("W/")) tag.remove_prefix(2);
    if (tag == "*" || tag == etag) return true;
    if (comma == std::string_view::npos) break;
    header.remove_prefix(comma + 1);
  }
  return false;
}

}  // namespace locator
