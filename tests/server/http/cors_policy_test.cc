#include "server/http/cors_policy.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/server/http/json_value.h"

namespace locator {
namespace {

using test::JsonValue;
using test::ParseJson;

constexpr char kAllowed[] = "https://app.example";

HttpRequest PreflightFrom(const std::string& origin) {
  HttpRequest request;
  request.method = "OPTIONS";
  request.path = "/v1/datasets/default:locate";
  request.headers = {{"origin", origin},
                     {"access-control-request-method", "POST"}};
  return request;
}

TEST(CorsPolicyTest, APreflightFromTheAllowedOriginGets204) {
  const CorsPolicy policy({kAllowed});
  const HttpRequest request = PreflightFrom(kAllowed);
  ASSERT_TRUE(policy.IsPreflight(request));
  const HttpResponse response = policy.Preflight(request);
  EXPECT_EQ(response.status, 204u);
  EXPECT_THAT(response.headers,
              ::testing::Contains(::testing::Pair("Access-Control-Allow-Origin",
                                                  std::string(kAllowed))));
}

// The refusal quotes the origin as every message quotes request text
// (QuotedInput: at most 80 bytes, control characters escaped): a 4 KiB Origin
// header is not echoed whole.
TEST(CorsPolicyTest, ARefusedOriginIsQuotedShort) {
  const CorsPolicy policy({kAllowed});
  const struct {
    std::string origin;
    std::string quoted;
  } rows[] = {
      {"http://evil.example.org", "'http://evil.example.org'"},
      {"https://" + std::string(4096, 'a'),
       "'https://" + std::string(72, 'a') + "...' (4104 bytes)"},
      {"null\x01", "'null\\x01'"},
  };
  for (const auto& row : rows) {
    const HttpResponse response = policy.Preflight(PreflightFrom(row.origin));
    EXPECT_EQ(response.status, 403u);
    JsonValue error;
    ASSERT_TRUE(ParseJson(response.body, &error).ok()) << response.body;
    EXPECT_EQ(error["message"].string(),
              "origin " + row.quoted +
                  " may not call this server (see --http-cors-origin)");
  }
}

}  // namespace
}  // namespace locator
