#include "server/serving/access_policy.h"

#include <openssl/crypto.h>
#include <openssl/sha.h>

#include <cctype>

namespace locator {
namespace {

// The scheme is case-insensitive (RFC 7235); the token is not.
constexpr std::string_view kBearer = "bearer ";

bool ParseBearer(std::optional<std::string_view> authorization,
                 std::string_view* token) {
  if (!authorization || authorization->size() <= kBearer.size()) return false;
  for (size_t i = 0; i < kBearer.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>((*authorization)[i])) !=
        kBearer[i]) {
      return false;
    }
  }
  *token = authorization->substr(kBearer.size());
  return token->find(' ') == std::string_view::npos;
}

}  // namespace

AccessPolicy::AccessPolicy(std::string_view data_token,
                           std::string_view admin_token) {
  if (!data_token.empty()) data_ = Sha256(data_token);
  if (!admin_token.empty()) admin_ = Sha256(admin_token);
}

AccessPolicy::Digest AccessPolicy::Sha256(std::string_view text) {
  Digest digest;
  SHA256(reinterpret_cast<const unsigned char*>(text.data()), text.size(),
         digest.data());
  return digest;
}

Status AccessPolicy::CheckAuthorization(
    std::optional<std::string_view> authorization, Scope scope) const {
  // The digests this RPC accepts; none at all means it is open.
  std::array<const Digest*, 2> accepted = {nullptr, nullptr};
  if (scope == Scope::kAdmin) {
    accepted[0] = admin_ ? &*admin_ : data_ ? &*data_ : nullptr;
  } else if (data_) {
    accepted = {&*data_, admin_ ? &*admin_ : nullptr};
  }
  if (accepted[0] == nullptr) return Status::OK();

  std::string_view token;
  if (!ParseBearer(authorization, &token)) {
    return Status::Unauthenticated(
        "expected 'authorization: Bearer <token>' (gRPC metadata or HTTP "
        "header)");
  }
  const Digest presented = Sha256(token);
  bool matched = false;
  // Both accepted digests are compared, so the time taken does not tell
  // which one (if any) matched.
  for (const Digest* digest : accepted) {
    if (digest == nullptr) continue;
    matched |=
        CRYPTO_memcmp(presented.data(), digest->data(), presented.size()) == 0;
  }
  if (matched) return Status::OK();
  return Status::PermissionDenied(
      scope == Scope::kAdmin ? "the bearer token is not accepted for admin RPCs"
                             : "the bearer token is not accepted");
}

}  // namespace locator
