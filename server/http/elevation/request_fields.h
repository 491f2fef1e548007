// RequestFields: the named parameters of an elevation API request, decoded
// once: a GET's query string, or a POST's body, either form encoded
// (application/x-www-form-urlencoded) or a JSON object (application/json)
// whose values are strings or numbers, as Open Topo Data reads them
// (https://www.opentopodata.org/api/). A POST's query string is not read,
// as Open Topo Data does not.
//
// Decoding is strict: a '%' not followed by two hex digits, a decoded NUL
// byte, a JSON body that is not an object, or a value that is neither a
// string nor a number is InvalidArgument naming the field. '+' is a space
// in both the query and the form, as HTML forms encode it.
//
// Thread-safety: a value type; const methods may be called concurrently.

#ifndef LOCATOR_SERVER_HTTP_ELEVATION_REQUEST_FIELDS_H_
#define LOCATOR_SERVER_HTTP_ELEVATION_REQUEST_FIELDS_H_

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "locator/status_or.h"
#include "server/http/http_server.h"

namespace locator {

// `text` with its %XX escapes decoded (and '+' as a space); InvalidArgument
// naming `field` for a bad escape or a NUL byte.
StatusOr<std::string> PercentDecoded(std::string_view text,
                                     std::string_view field);

class RequestFields {
 public:
  // The fields of `request` (see above).
  static StatusOr<RequestFields> Of(const HttpRequest& request);
  // The fields of a query string or a form body.
  static StatusOr<RequestFields> OfForm(std::string_view form);

  // The value of the first field `name`, or nullopt.
  std::optional<std::string_view> Get(std::string_view name) const;

 private:
  std::vector<std::pair<std::string, std::string>> fields_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_ELEVATION_REQUEST_FIELDS_H_
