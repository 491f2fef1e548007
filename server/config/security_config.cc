#include "server/config/security_config.h"

#include <limits>
#include <utility>

#include "common/credential_files.h"

namespace locator {
namespace {

// gRPC takes every channel argument as an int.
constexpr uint64_t kMaxIntArg = std::numeric_limits<int>::max();

// The connection limits: whole numbers, each a gRPC channel argument.
struct IntFlag {
  const char* name;
  const char* help;
  uint64_t min;
  int TransportConfig::*value;
};

// gRPC clamps keepalive times below 10 s for clients, not for servers; 1 ms
// is allowed so that tests can exercise the limits quickly.
constexpr IntFlag kIntFlags[] = {
    // A connection must be able to carry at least one call.
    {"max-concurrent-streams", "calls one connection may have open at once", 1,
     &TransportConfig::max_concurrent_streams},
    {"keepalive-time-ms", "ping a quiet connection this often", 1,
     &TransportConfig::keepalive_time_ms},
    {"keepalive-timeout-ms",
     "close a connection whose ping is not answered within this time", 1,
     &TransportConfig::keepalive_timeout_ms},
    {"min-ping-interval-ms",
     "client pings closer together than this are strikes", 0,
     &TransportConfig::min_ping_interval_ms},
    {"max-ping-strikes",
     "close a connection after this many ping strikes (too_many_pings); 0 = "
     "never",
     0, &TransportConfig::max_ping_strikes},
};

}  // namespace

void AddTransportFlags(TransportConfig* config, TransportFiles* files,
                       FlagSet* flags) {
  flags->Add("tls-cert", flag::Text(&files->tls_cert).Shape("FILE"),
             "serve TLS with this PEM certificate chain (needs --tls-key)");
  flags->Add("tls-key", flag::Text(&files->tls_key).Shape("FILE"),
             "PEM private key of --tls-cert (unencrypted)");
  flags->Add("tls-client-ca", flag::Text(&files->tls_client_ca).Shape("FILE"),
             "mutual TLS: require client certificates signed by this PEM CA");
  for (const IntFlag& flag : kIntFlags) {
    flags->Add(flag.name,
               flag::Count(&(config->*flag.value), flag.min, kMaxIntArg),
               flag.help);
  }
  flags->Add("default-deadline-ms",
             flag::CountInto(0, kMaxIntArg, config->default_deadline.count(),
                             [config](uint64_t ms) {
                               config->default_deadline =
                                   std::chrono::milliseconds(ms);
                             }),
             "deadline of a call whose client set none (LocateBatch, "
             "LocateStream); 0 = none");
}

Status ReadTransportFiles(const TransportFiles& files,
                          TransportConfig* config) {
  TlsConfig& tls = config->tls;
  if (!files.tls_client_ca.empty() && files.tls_cert.empty()) {
    return Status::InvalidArgument(
        "--tls-client-ca needs --tls-cert and --tls-key");
  }
  KeyPairPem pair;
  Status status = ReadKeyPairFiles("", files.tls_cert, files.tls_key, &pair);
  if (!status.ok()) return status;
  tls.cert_chain_pem = std::move(pair.cert_chain);
  tls.private_key_pem = std::move(pair.private_key);
  if (!files.tls_client_ca.empty()) {
    status = ReadPemFile("tls-client-ca", files.tls_client_ca,
                         PemKind::kCertificates, &tls.client_ca_pem);
  }
  return status;
}

void AddAccessFlags(AccessConfig* config, AccessFiles* files, FlagSet* flags) {
  flags->Add("token-file", flag::Text(&files->token_file).Shape("FILE"),
             "require 'authorization: Bearer <token>' with this file's token "
             "on every RPC (the admin token is accepted too)");
  flags->Add("admin-token-file",
             flag::Text(&files->admin_token_file).Shape("FILE"),
             "require this file's token on admin RPCs (Retune, Reload)");
  flags->Add("redact", flag::Switch(&config->redact),
             "no output reveals a file path: GetStats, Retune and Reload "
             "answers, /api/stats and /metrics leave the dataset source and "
             "the state path empty");
}

Status ReadAccessFiles(const AccessFiles& files, AccessConfig* config) {
  Status status;
  if (!files.token_file.empty()) {
    status = ReadTokenFile("token-file", files.token_file, &config->data_token);
  }
  if (status.ok() && !files.admin_token_file.empty()) {
    status = ReadTokenFile("admin-token-file", files.admin_token_file,
                           &config->admin_token);
  }
  // Otherwise every data client could call the admin RPCs.
  if (status.ok() && !config->admin_token.empty() &&
      config->admin_token == config->data_token) {
    return Status::InvalidArgument(
        "--token-file and --admin-token-file hold the same token");
  }
  return status;
}

}  // namespace locator
