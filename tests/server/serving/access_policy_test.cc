// AccessPolicy's decisions, one row per case of the table in
// server/serving/access_policy.h.

#include "server/serving/access_policy.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace locator {
namespace {

using Scope = AccessPolicy::Scope;

constexpr Status::Code kOk = Status::Code::kOk;
constexpr Status::Code kUnauthenticated = Status::Code::kUnauthenticated;
constexpr Status::Code kDenied = Status::Code::kPermissionDenied;

struct Case {
  std::string data_token;
  std::string admin_token;
  std::optional<std::string> authorization;
  Scope scope;
  Status::Code want;
};

TEST(AccessPolicyTest, EveryCombinationOfTokensAndScopes) {
  const std::optional<std::string> none;
  const std::vector<Case> cases = {
      // No tokens: everything open, whatever the call carries.
      {"", "", none, Scope::kData, kOk},
      {"", "", none, Scope::kAdmin, kOk},
      {"", "", "Bearer junk", Scope::kAdmin, kOk},
      // Data token only: it guards both scopes.
      {"data", "", none, Scope::kData, kUnauthenticated},
      {"data", "", "Bearer data", Scope::kData, kOk},
      {"data", "", "Bearer data", Scope::kAdmin, kOk},
      {"data", "", "Bearer dat", Scope::kData, kDenied},
      {"data", "", "Bearer data2", Scope::kAdmin, kDenied},
      // Admin token only: data RPCs stay open.
      {"", "admin", none, Scope::kData, kOk},
      {"", "admin", none, Scope::kAdmin, kUnauthenticated},
      {"", "admin", "Bearer admin", Scope::kAdmin, kOk},
      {"", "admin", "Bearer data", Scope::kAdmin, kDenied},
      // Both: the admin token also works for data RPCs, not vice versa.
      {"data", "admin", "Bearer data", Scope::kData, kOk},
      {"data", "admin", "Bearer admin", Scope::kData, kOk},
      {"data", "admin", "Bearer admin", Scope::kAdmin, kOk},
      {"data", "admin", "Bearer data", Scope::kAdmin, kDenied},
      {"data", "admin", "Bearer other", Scope::kData, kDenied},
      // Malformed headers are unauthenticated, not denied.
      {"data", "", "data", Scope::kData, kUnauthenticated},
      {"data", "", "Basic data", Scope::kData, kUnauthenticated},
      {"data", "", "Bearer ", Scope::kData, kUnauthenticated},
      {"data", "", "Bearer data extra", Scope::kData, kUnauthenticated},
      {"data", "", "Bearerdata", Scope::kData, kUnauthenticated},
      // The scheme is case-insensitive, the token is not.
      {"data", "", "bearer data", Scope::kData, kOk},
      {"data", "", "BEARER data", Scope::kData, kOk},
      {"data", "", "Bearer DATA", Scope::kData, kDenied},
  };
  for (const Case& c : cases) {
    const AccessPolicy policy(c.data_token, c.admin_token);
    std::optional<std::string_view> authorization;
    if (c.authorization) authorization = *c.authorization;
    const Status status = policy.CheckAuthorization(authorization, c.scope);
    EXPECT_EQ(status.code(), c.want)
        << "data='" << c.data_token << "' admin='" << c.admin_token
        << "' authorization='" << c.authorization.value_or("<none>")
        << "' scope=" << (c.scope == Scope::kAdmin ? "admin" : "data") << ": "
        << status.message();
  }
}

TEST(AccessPolicyTest, RefusalsSayWhatIsExpectedWithoutEchoingTheToken) {
  const AccessPolicy policy("data", "admin");
  const Status missing = policy.CheckAuthorization(std::nullopt, Scope::kData);
  EXPECT_EQ(missing.message(),
            "expected 'authorization: Bearer <token>' (gRPC metadata or HTTP "
            "header)");
  const Status wrong = policy.CheckAuthorization("Bearer guess", Scope::kAdmin);
  EXPECT_EQ(wrong.message(), "the bearer token is not accepted for admin RPCs");
}

}  // namespace
}  // namespace locator
