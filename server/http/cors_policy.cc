#include "server/http/cors_policy.h"

#include <algorithm>
#include <optional>
#include <string_view>
#include <utility>

#include "common/input_text.h"
#include "server/http/api_error.h"

namespace locator {

CorsPolicy::CorsPolicy(std::vector<std::string> origins)
    : origins_(std::move(origins)) {}

bool CorsPolicy::Allows(std::optional<std::string_view> origin) const {
  return origin.has_value() &&
         std::find(origins_.begin(), origins_.end(), *origin) != origins_.end();
}

bool CorsPolicy::IsPreflight(const HttpRequest& request) const {
  return !origins_.empty() && request.method == "OPTIONS" &&
         request.Header("origin").has_value() &&
         request.Header("access-control-request-method").has_value();
}

HttpResponse CorsPolicy::Preflight(const HttpRequest& request) const {
  const std::optional<std::string_view> origin = request.Header("origin");
  if (!Allows(origin)) {
    return ApiError(Status::PermissionDenied(
        "origin " + QuotedInput(origin.value_or("")) +
        " may not call this server (see --http-cors-origin)"));
  }
  HttpResponse response;
  response.status = 204;
  response.headers = {
      {"Access-Control-Allow-Methods", "GET, POST, OPTIONS"},
      {"Access-Control-Allow-Headers", "Authorization, Content-Type"},
      {"Access-Control-Max-Age", std::to_string(kPreflightMaxAgeSeconds)}};
  Apply(origin, &response);
  return response;
}

void CorsPolicy::Apply(std::optional<std::string_view> origin,
                       HttpResponse* response) const {
  if (origins_.empty()) return;
  response->headers.emplace_back("Vary", "Origin");
  if (!Allows(origin)) return;
  response->headers.emplace_back("Access-Control-Allow-Origin",
                                 std::string(*origin));
}

}  // namespace locator
