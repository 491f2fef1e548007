// QueryParameter: one parameter of a URL's query string, as the HTTP
// server hands it over (HttpRequest::query, undecoded).
//
// Thread-safety: a pure function.

#ifndef LOCATOR_SERVER_HTTP_QUERY_STRING_H_
#define LOCATOR_SERVER_HTTP_QUERY_STRING_H_

#include <string_view>

namespace locator {

// The value of the first parameter `name` in the query string `query` (""
// if absent), not percent-decoded: for values of [A-Za-z0-9_.-] such as
// dataset names and encodings, which need none.
std::string_view QueryParameter(std::string_view query, std::string_view name);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_QUERY_STRING_H_
