// CorsPolicy: which web origins may call locatord's HTTP server from their
// pages (Cross-Origin Resource Sharing), by exact match against the
// --http-cors-origin list.
//
// For an allowed origin, every answer carries Access-Control-Allow-Origin
// (that origin) and Vary: Origin, and a preflight (OPTIONS with Origin and
// Access-Control-Request-Method) gets 204 with the methods (GET, POST,
// OPTIONS) and request headers (Authorization, Content-Type) it may use. A
// preflight from another origin gets 403 and an ApiError body, and other
// answers to it carry no CORS header, so the browser keeps them from the
// page. With no origin configured CORS is off: no CORS header is ever sent
// and OPTIONS is a method like any other.
//
// Immutable after construction; thread-safe.

#ifndef LOCATOR_SERVER_HTTP_CORS_POLICY_H_
#define LOCATOR_SERVER_HTTP_CORS_POLICY_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "server/http/http_server.h"

namespace locator {

class CorsPolicy {
 public:
  // Seconds a browser may cache a preflight's answer.
  static constexpr int kPreflightMaxAgeSeconds = 600;

  // Allows exactly `origins` (scheme://host[:port]); none: CORS off.
  explicit CorsPolicy(std::vector<std::string> origins);

  // Whether `request` is a preflight this policy answers (CORS on).
  bool IsPreflight(const HttpRequest& request) const;
  // The answer to the preflight `request`.
  HttpResponse Preflight(const HttpRequest& request) const;
  // Adds the CORS headers to `response` for a request from `origin` (its
  // Origin header; nullopt without one).
  void Apply(std::optional<std::string_view> origin,
             HttpResponse* response) const;

 private:
  // Whether `origin` is an allowed origin.
  bool Allows(std::optional<std::string_view> origin) const;

  const std::vector<std::string> origins_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_CORS_POLICY_H_
