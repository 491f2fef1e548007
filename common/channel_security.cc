#include "common/channel_security.h"

#include <utility>

#include "common/credential_files.h"

namespace locator {

void AddChannelTlsFlags(std::string_view prefix,
                        ChannelSecurityFlags* security_flags, FlagSet* flags) {
  ChannelSecurityFlags& f = *security_flags;
  const std::string p(prefix);
  flags->Add(p + "tls", flag::Switch(&f.tls),
             "speak TLS (implied by the other --" + p +
                 "tls flags); without --" + p +
                 "tls-ca, trust the system's roots");
  flags->Add(p + "tls-ca", flag::Text(&f.tls_ca).Shape("FILE"),
             "trust servers whose certificate this PEM CA signed");
  flags->Add(p + "tls-cert", flag::Text(&f.tls_cert).Shape("FILE"),
             "mutual TLS: present this PEM certificate chain (needs --" + p +
                 "tls-key)");
  flags->Add(p + "tls-key", flag::Text(&f.tls_key).Shape("FILE"),
             "PEM private key of --" + p + "tls-cert (unencrypted)");
  flags->Add(p + "tls-server-name",
             flag::Text(&f.tls_server_name).Shape("NAME"),
             "check the server's certificate against this name instead of the "
             "target's host");
}

void AddChannelSecurityFlags(ChannelSecurityFlags* security_flags,
                             FlagSet* flags) {
  flags->Add("token-file",
             flag::Text(&security_flags->token_file).Shape("FILE"),
             "send this file's token as 'authorization: Bearer <token>' on "
             "every call");
  AddChannelTlsFlags("", security_flags, flags);
}

Status LoadChannelSecurity(const ChannelSecurityFlags& flags,
                           ChannelSecurity* security,
                           std::string_view flag_prefix) {
  *security = ChannelSecurity();
  // A key alone fails below, in ReadKeyPairFiles.
  security->tls = flags.AnyTls();
  security->server_name = flags.tls_server_name;
  KeyPairPem pair;
  Status status =
      ReadKeyPairFiles(flag_prefix, flags.tls_cert, flags.tls_key, &pair);
  security->cert_chain_pem = std::move(pair.cert_chain);
  security->private_key_pem = std::move(pair.private_key);
  if (status.ok() && !flags.token_file.empty()) {
    status =
        ReadTokenFile("token-file", flags.token_file, &security->bearer_token);
  }
  if (status.ok() && !flags.tls_ca.empty()) {
    status = ReadPemFile(std::string(flag_prefix) + "tls-ca", flags.tls_ca,
                         PemKind::kCertificates, &security->root_pem);
  }
  return status;
}

}  // namespace locator
