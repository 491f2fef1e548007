// Security and limits flags: TLS, connection limits, keepalive enforcement
// and the server's default deadline (both servers: TransportConfig), and the
// bearer tokens and redaction of locatord (AccessConfig). Defaults are
// documented in README.md ("Security and limits") and in --help.
//
// Token and PEM files are read once, while the flags are read: a file that
// cannot be read, is empty or does not parse fails startup with a message
// naming the flag and the file (exit code 2, like any bad flag).
//
// Thread-safety: plain values and free functions.

#ifndef LOCATOR_SERVER_SECURITY_CONFIG_H_
#define LOCATOR_SERVER_SECURITY_CONFIG_H_

#include <chrono>
#include <string>

#include "common/flags/flag_set.h"
#include "locator/status.h"

namespace locator {

// TLS on the listening port; plaintext when cert_chain_pem is empty.
struct TlsConfig {
  // --tls-cert and --tls-key: the server's certificate chain and key (PEM).
  std::string cert_chain_pem;
  std::string private_key_pem;
  // --tls-client-ca: when set, every client must present a certificate
  // signed by this CA (mutual TLS).
  std::string client_ca_pem;

  bool enabled() const { return !cert_chain_pem.empty(); }
};

struct TransportConfig {
  TlsConfig tls;
  // --max-concurrent-streams: calls one HTTP/2 connection may have open at
  // once; further calls wait in the client until one ends.
  int max_concurrent_streams = 100;
  // --keepalive-time-ms / --keepalive-timeout-ms: the server pings a quiet
  // connection this often and closes it when a ping goes unanswered.
  int keepalive_time_ms = 60'000;
  int keepalive_timeout_ms = 20'000;
  // --min-ping-interval-ms / --max-ping-strikes: a client ping sooner than
  // this after the previous one is a strike; after this many strikes the
  // server closes the connection (GOAWAY "too_many_pings").
  int min_ping_interval_ms = 10'000;
  int max_ping_strikes = 2;
  // --default-deadline-ms: the deadline of a call whose client set none;
  // zero means none.
  std::chrono::milliseconds default_deadline{30'000};
};

// Who may call locatord's RPCs (see server/serving/access_policy.h) and what
// GetStats may reveal.
struct AccessConfig {
  // --token-file: required on every RPC when set (empty: not required).
  std::string data_token;
  // --admin-token-file: required on admin RPCs when set.
  std::string admin_token;
  // --redact: no output of the statistics shows a file path (see
  // RedactStats).
  bool redact = false;
};

// The files the flags name, read after parsing by ReadTransportFiles /
// ReadAccessFiles (empty: not given).
struct TransportFiles {
  std::string tls_cert;
  std::string tls_key;
  std::string tls_client_ca;
};

struct AccessFiles {
  std::string token_file;
  std::string admin_token_file;
};

// Declares the transport flags on `flags`: the limits go straight into
// `config` (its values are the defaults), the PEM file names into `files`.
// Both must outlive the parse.
void AddTransportFlags(TransportConfig* config, TransportFiles* files,
                       FlagSet* flags);
// Reads the PEM files `files` names into `config`; InvalidArgument naming
// the flag and the file when one cannot be read or does not parse, or when
// the flags do not go together.
Status ReadTransportFiles(const TransportFiles& files, TransportConfig* config);

// Declares locatord's access flags on `flags` (--redact into `config`, the
// token file names into `files`).
void AddAccessFlags(AccessConfig* config, AccessFiles* files, FlagSet* flags);
// Reads the token files into `config`.
Status ReadAccessFiles(const AccessFiles& files, AccessConfig* config);

}  // namespace locator

#endif  // LOCATOR_SERVER_SECURITY_CONFIG_H_
