// The answers every route of the HTTP/JSON API gives alike: a message as
// JSON, no such route (404), a method the path does not take (405), and
// the If-None-Match test of the routes with entity tags.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_HTTP_JSON_API_ANSWERS_H_
#define LOCATOR_SERVER_HTTP_JSON_API_ANSWERS_H_

#include <google/protobuf/message.h>

#include <string>
#include <string_view>

#include "common/input_text.h"
#include "locator/status.h"
#include "server/http/http_server.h"

namespace locator {

// Parses `body` ("": {}) into *out in protobuf's JSON mapping (unknown
// fields are errors): InvalidArgument naming the parse error otherwise.
[[nodiscard]] Status ParseJsonMessage(std::string_view body,
                                      google::protobuf::Message* out);

// Parses the body of a request for dataset `dataset` (the path's) into
// *out, whose `dataset` field it sets. ParseJsonMessage's error, or
// InvalidArgument for a body naming a `dataset` other than the path's.
template <typename Request>
Status ParseBody(const HttpRequest& request, std::string_view dataset,
                 Request* out) {
  if (Status parsed = ParseJsonMessage(request.body, out); !parsed.ok()) {
    return parsed;
  }
  if (!out->dataset().empty() && out->dataset() != dataset) {
    return Status::InvalidArgument(
        "the body names dataset " + QuotedInput(out->dataset()) +
        " but the path names " + QuotedInput(dataset));
  }
  out->set_dataset(std::string(dataset));
  return Status::OK();
}

// 200 with `message` as ProtoJson prints it.
HttpResponse JsonAnswer(const google::protobuf::Message& message);

// NOT_FOUND naming the request's method and path and the API's routes.
HttpResponse NoRoute(const HttpRequest& request);

// 405 UNIMPLEMENTED with Allow: `allowed` (e.g. "GET").
HttpResponse MethodNotAllowed(const HttpRequest& request,
                              std::string_view allowed);

// Whether the If-None-Match value `header` names `etag` (or is "*"); weak
// tags (W/"...") compare by their tag, as RFC 9110 says for GET.
bool NamesETag(std::string_view header, std::string_view etag);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_JSON_API_ANSWERS_H_
