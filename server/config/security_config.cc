#include "server/config/security_config.h"

#include <boost/program_options.hpp>
#include <limits>
#include <utility>

#include "common/credential_files.h"
#include "server/config/flag_parsing.h"

namespace locator {
namespace {

namespace po = boost::program_options;

// gRPC takes every channel argument as an int.
constexpr uint64_t kMaxIntArg = std::numeric_limits<int>::max();

// The connection limits: whole numbers, each a gRPC channel argument.
struct IntFlag {
  const char* name;
  const char* help;
  uint64_t min;
  std::string TransportFlags::*text;
  int TransportConfig::*value;
};

// gRPC clamps keepalive times below 10 s for clients, not for servers; 1 ms
// is allowed so that tests can exercise the limits quickly.
constexpr IntFlag kIntFlags[] = {
    // A connection must be able to carry at least one call.
    {"max-concurrent-streams", "calls one connection may have open at once", 1,
     &TransportFlags::max_concurrent_streams,
     &TransportConfig::max_concurrent_streams},
    {"keepalive-time-ms", "ping a quiet connection this often", 1,
     &TransportFlags::keepalive_time_ms, &TransportConfig::keepalive_time_ms},
    {"keepalive-timeout-ms",
     "close a connection whose ping is not answered within this time", 1,
     &TransportFlags::keepalive_timeout_ms,
     &TransportConfig::keepalive_timeout_ms},
    {"min-ping-interval-ms",
     "client pings closer together than this are strikes", 0,
     &TransportFlags::min_ping_interval_ms,
     &TransportConfig::min_ping_interval_ms},
    {"max-ping-strikes",
     "close a connection after this many ping strikes (too_many_pings); 0 = "
     "never",
     0, &TransportFlags::max_ping_strikes, &TransportConfig::max_ping_strikes},
};

Status ReadTlsFlags(const TransportFlags& flags, TlsConfig* tls) {
  if (!flags.tls_client_ca.empty() && flags.tls_cert.empty()) {
    return Status::InvalidArgument(
        "--tls-client-ca needs --tls-cert and --tls-key");
  }
  KeyPairPem pair;
  Status status = ReadKeyPairFiles(flags.tls_cert, flags.tls_key, &pair);
  if (!status.ok()) return status;
  tls->cert_chain_pem = std::move(pair.cert_chain);
  tls->private_key_pem = std::move(pair.private_key);
  if (!flags.tls_client_ca.empty()) {
    status = ReadPemFile("tls-client-ca", flags.tls_client_ca,
                         PemKind::kCertificates, &tls->client_ca_pem);
  }
  return status;
}

}  // namespace

void AddTransportFlags(const TransportConfig& defaults, TransportFlags* flags,
                       po::options_description* options) {
  options->add_options()(
      "tls-cert", po::value(&flags->tls_cert),
      "serve TLS with this PEM certificate chain (needs --tls-key)")(
      "tls-key", po::value(&flags->tls_key),
      "PEM private key of --tls-cert (unencrypted)")(
      "tls-client-ca", po::value(&flags->tls_client_ca),
      "mutual TLS: require client certificates signed by this PEM CA");
  for (const IntFlag& flag : kIntFlags) {
    options->add_options()(
        flag.name,
        po::value(&(flags->*flag.text))
            ->default_value(std::to_string(defaults.*flag.value)),
        flag.help);
  }
  options->add_options()(
      "default-deadline-ms",
      po::value(&flags->default_deadline_ms)
          ->default_value(std::to_string(defaults.default_deadline.count())),
      "deadline of a call whose client set none (LocateBatch, "
      "LocateStream); 0 = none");
}

Status ReadTransportFlags(const TransportFlags& flags,
                          TransportConfig* config) {
  Status status = ReadTlsFlags(flags, &config->tls);
  for (const IntFlag& flag : kIntFlags) {
    if (!status.ok()) return status;
    status = ParseCountAs(flag.name, flags.*flag.text, flag.min, kMaxIntArg,
                          &(config->*flag.value));
  }
  int64_t deadline_ms = 0;
  if (status.ok()) {
    status = ParseCountAs("default-deadline-ms", flags.default_deadline_ms, 0,
                          kMaxIntArg, &deadline_ms);
  }
  if (status.ok()) {
    config->default_deadline = std::chrono::milliseconds(deadline_ms);
  }
  return status;
}

void AddAccessFlags(AccessFlags* flags, po::options_description* options) {
  options->add_options()(
      "token-file", po::value(&flags->token_file),
      "require 'authorization: Bearer <token>' with this file's token on "
      "every RPC (the admin token is accepted too)")(
      "admin-token-file", po::value(&flags->admin_token_file),
      "require this file's token on admin RPCs (Retune, Reload)")(
      "redact", po::bool_switch(&flags->redact),
      "no output reveals a file path: GetStats, Retune and Reload answers, "
      "/api/stats and /metrics leave the dataset source and the state path "
      "empty");
}

Status ReadAccessFlags(const AccessFlags& flags, AccessConfig* config) {
  config->redact = flags.redact;
  Status status;
  if (!flags.token_file.empty()) {
    status = ReadTokenFile("token-file", flags.token_file, &config->data_token);
  }
  if (status.ok() && !flags.admin_token_file.empty()) {
    status = ReadTokenFile("admin-token-file", flags.admin_token_file,
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
