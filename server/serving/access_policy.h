// AccessPolicy: which calls locatord accepts, from the bearer tokens it was
// given (--token-file, --admin-token-file).
//
//   tokens given     data RPCs (Locate*, GetStats)   admin RPCs (Retune, ...)
//   none             open                            open
//   data only        the data token                  the data token
//   admin only       open                            the admin token
//   both             the data or the admin token     the admin token
//
// A call presents a token as metadata (gRPC) or header (HTTP)
// "authorization: Bearer <token>".
// Missing or malformed: UNAUTHENTICATED. Well formed but not accepted for
// this RPC: PERMISSION_DENIED. Tokens are compared as SHA-256 digests with
// CRYPTO_memcmp, so neither the time a comparison takes nor the token's
// length tells a caller how close a guess came. The health service and
// reflection are not behind the policy (probes carry no token).
//
// Holds the tokens' digests only. Thread-safety: immutable after
// construction; CheckAuthorization() may be called concurrently.

#ifndef LOCATOR_SERVER_ACCESS_POLICY_H_
#define LOCATOR_SERVER_ACCESS_POLICY_H_

#include <array>
#include <optional>
#include <string_view>

#include "locator/status.h"

namespace locator {

class AccessPolicy {
 public:
  enum class Scope {
    kData,   // Locate, LocateBatch, LocateStream, GetStats
    kAdmin,  // Retune and every other RPC that changes the server's state
  };

  // Empty tokens are not required (see the table above).
  AccessPolicy(std::string_view data_token, std::string_view admin_token);

  // OK if a call presenting `authorization` (an "authorization" metadata or
  // HTTP header value; nullopt when the call has none) may run an RPC of
  // `scope`; otherwise the refusal to finish it with. gRPC and HTTP calls
  // alike are admitted by it (LocatorApp::Admit).
  Status CheckAuthorization(std::optional<std::string_view> authorization,
                            Scope scope) const;

 private:
  using Digest = std::array<unsigned char, 32>;

  static Digest Sha256(std::string_view text);

  std::optional<Digest> data_;
  std::optional<Digest> admin_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ACCESS_POLICY_H_
