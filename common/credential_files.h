// Credential files: bearer tokens and PEM certificates and keys, read once at
// startup by locatord and by the clients (`locator`, `locator-load`).
//
// Every error is InvalidArgument "--<flag> '<path>': <problem>", naming the
// flag and the file; a file's contents never appear in a message. Files are
// small: anything over kMaxCredentialFileBytes is refused rather than read
// (a token flag pointed at a device or a dataset by mistake).
//
// Thread-safety: free functions.

#ifndef LOCATOR_COMMON_CREDENTIAL_FILES_H_
#define LOCATOR_COMMON_CREDENTIAL_FILES_H_

#include <cstddef>
#include <string>
#include <string_view>

#include "locator/status.h"

namespace locator {

inline constexpr size_t kMaxCredentialFileBytes = size_t{1} << 20;

// Reads a bearer token: the file's one line, without its trailing newline
// (LF or CRLF). The token must be non-empty printable ASCII without spaces,
// which is what an HTTP/2 header value can carry as "Bearer <token>".
Status ReadTokenFile(std::string_view flag, const std::string& path,
                     std::string* token);

enum class PemKind {
  kCertificates,  // one or more certificates (a chain, or CA roots)
  kPrivateKey,
};

// Reads a PEM file and checks with OpenSSL that it holds `kind`.
Status ReadPemFile(std::string_view flag, const std::string& path, PemKind kind,
                   std::string* pem);

// A certificate chain and its private key, as PEM.
struct KeyPairPem {
  std::string cert_chain;
  std::string private_key;
};

// Reads --<flag_prefix>tls-cert and --<flag_prefix>tls-key (`cert_path`,
// `key_path`): both or neither must be given (neither leaves `pair` empty),
// and the key must be the private key of the chain's first certificate.
Status ReadKeyPairFiles(std::string_view flag_prefix,
                        const std::string& cert_path,
                        const std::string& key_path, KeyPairPem* pair);

}  // namespace locator

#endif  // LOCATOR_COMMON_CREDENTIAL_FILES_H_
