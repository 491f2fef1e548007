#include "server/config/http_flags.h"

#include <limits>
#include <string>

#include "common/status_macros.h"

namespace locator {
namespace {

// An exact origin as browsers send it: http(s)://host[:port], nothing after.
Status CheckCorsOrigin(const std::string& origin) {
  const size_t scheme_end = origin.find("://");
  const std::string_view scheme = std::string_view(origin).substr(
      0, scheme_end == std::string::npos ? 0 : scheme_end);
  if (scheme != "http" && scheme != "https") {
    return FlagError("http-cors-origin", origin,
                     "expected http://HOST[:PORT] or https://HOST[:PORT]");
  }
  const std::string_view rest = std::string_view(origin).substr(scheme_end + 3);
  if (rest.empty() || rest.find_first_of("/?#* ") != std::string_view::npos) {
    return FlagError("http-cors-origin", origin,
                     "an origin is scheme://host[:port] exactly, without a "
                     "path or wildcards");
  }
  return Status::OK();
}

}  // namespace

void AddHttpFlags(ServerConfig* config, FlagSet* flags) {
  flags->Add("http-listen", flag::Parsed([config](std::string_view text) {
                              if (text.empty()) {
                                config->http_host.clear();
                                return Status::OK();
                              }
                              return ParseListenAddress(
                                  text, &config->http_host, &config->http_port);
                            }).Shape("HOST:PORT"),
             "HOST:PORT for /metrics, the status page, the web map (/web/) "
             "and the HTTP/JSON API (/v1/); port 0 lets the OS pick (the "
             "chosen port is printed); empty = off");
  flags->Add("http-max-body-bytes",
             flag::Bytes(&config->http_max_body_bytes, 1024,
                         std::numeric_limits<uint32_t>::max()),
             "larger HTTP request bodies get 413");
  flags->Add("http-cors-origin",
             flag::Repeated(&config->http_cors_origins).Shape("ORIGIN"),
             "an origin (scheme://host[:port], exact) whose web pages may "
             "call the HTTP server (CORS); repeatable; none = CORS off");
  // An HTTP :grid answers every cell in one protobuf repeated field.
  flags->Add("http-max-grid-cells",
             flag::Count(&config->http_max_grid_cells, 1,
                         std::numeric_limits<int>::max()),
             "an HTTP :grid of more cells fails with RESOURCE_EXHAUSTED (its "
             "answer is one JSON text of ~20 bytes per cell; gRPC streams up "
             "to --max-grid-cells)");
  flags->Add("http-max-connections-per-address",
             flag::Count(&config->http_max_connections_per_address, 1,
                         config->http_max_connections),
             "HTTP connections one client address may hold open; more get 503 "
             "(behind a reverse proxy, every client has the proxy's address)");
  // Each waiting call holds a connection: more could never wait.
  flags->Add("http-max-waiting-calls",
             flag::Count(&config->http_max_waiting_calls, 1,
                         config->http_max_connections),
             "HTTP API calls that may wait for a thread in each lane (cheap: "
             ":locate and small batches; expensive: :profile, :grid, large "
             "batches); a call finding that many waiting gets 503 with "
             "Retry-After");
  flags->Add("http-public-status", flag::Switch(&config->http_public_status),
             "/api/stats and /api/edges answer without a token even with "
             "--token-file (they show the dataset's source and coordinates)");
}

Status CheckHttpFlags(const ServerConfig& config) {
  for (const std::string& origin : config.http_cors_origins) {
    RETURN_IF_ERROR(CheckCorsOrigin(origin));
  }
  return Status::OK();
}

}  // namespace locator
