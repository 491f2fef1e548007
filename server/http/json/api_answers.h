// The answers every route of the HTTP/JSON API gives alike: a message as
// JSON, no such route (404), a method the path does not take (405), and
// the If-None-Match test of the routes with entity tags.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_HTTP_JSON_API_ANSWERS_H_
#define LOCATOR_SERVER_HTTP_JSON_API_ANSWERS_H_

#include <google/protobuf/message.h>

#include <string_view>

#include "server/http/http_server.h"

namespace locator {

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
