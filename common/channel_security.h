// ChannelSecurity: how a client channel to a locator server is secured (TLS,
// mutual TLS, a bearer token), and the flags that say so.
//
// The flags --token-file, --tls, --tls-ca, --tls-cert, --tls-key and
// --tls-server-name are declared and read here, once for every client
// (`locator`, `locator-load`: AddChannelSecurityFlags, LoadChannelSecurity),
// and so are the router's TLS flags to its shards (AddChannelTlsFlags with
// the prefix "shard-"). channel_options.h builds channels from them. No
// gRPC here: the server's configuration reads these flags too.
//
// Thread-safety: plain values and free functions.

#ifndef LOCATOR_COMMON_CHANNEL_SECURITY_H_
#define LOCATOR_COMMON_CHANNEL_SECURITY_H_

#include <string>
#include <string_view>

#include "common/flags/flag_set.h"
#include "locator/status.h"

namespace locator {

// Credentials, as read from the files the flags name.
struct ChannelSecurity {
  // Sent as "authorization: Bearer <token>" on every call; empty: none.
  std::string bearer_token;
  // Speak TLS. Without root_pem, gRPC's default roots are trusted.
  bool tls = false;
  std::string root_pem;
  // The client's certificate chain and key, for mutual TLS.
  std::string cert_chain_pem;
  std::string private_key_pem;
  // The name the server's certificate is checked against instead of the
  // target's host (e.g. "localhost" when dialling 127.0.0.1).
  std::string server_name;
};

// The security flags as typed.
struct ChannelSecurityFlags {
  // Whether any TLS flag was given (each implies --tls).
  bool AnyTls() const {
    return tls || !tls_ca.empty() || !tls_cert.empty() || !tls_key.empty() ||
           !tls_server_name.empty();
  }

  std::string token_file;
  bool tls = false;
  std::string tls_ca;
  std::string tls_cert;
  std::string tls_key;
  std::string tls_server_name;
};

// Declares the security flags on `flags`, into `security_flags`, which
// must outlive the parse.
void AddChannelSecurityFlags(ChannelSecurityFlags* security_flags,
                             FlagSet* flags);

// Declares the TLS flags alone, each named with `prefix` first
// (--<prefix>tls, --<prefix>tls-ca, ...): the router's to its shards.
void AddChannelTlsFlags(std::string_view prefix,
                        ChannelSecurityFlags* security_flags, FlagSet* flags);

// Reads the files the flags name into `security`. InvalidArgument naming
// the flag (with `flag_prefix`) and the file when one cannot be read or
// does not parse, or when the flags do not go together.
Status LoadChannelSecurity(const ChannelSecurityFlags& flags,
                           ChannelSecurity* security,
                           std::string_view flag_prefix = "");

}  // namespace locator

#endif  // LOCATOR_COMMON_CHANNEL_SECURITY_H_
