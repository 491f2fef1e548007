// locatord's HTTP flags: where the HTTP server listens (--http-listen; off
// by default) and its limits, CORS origins and public status pages.
//
// Thread-safety: free functions over plain values.

#ifndef LOCATOR_SERVER_CONFIG_HTTP_FLAGS_H_
#define LOCATOR_SERVER_CONFIG_HTTP_FLAGS_H_

#include "common/flags/flag_set.h"
#include "locator/status.h"
#include "server/config/server_config.h"

namespace locator {

// Declares the HTTP flags on `flags`, into `config` (whose values are the
// defaults); `config` must outlive the parse.
void AddHttpFlags(ServerConfig* config, FlagSet* flags);

// Checks each --http-cors-origin is an exact origin,
// http(s)://host[:port]; InvalidArgument naming the flag otherwise.
Status CheckHttpFlags(const ServerConfig& config);

}  // namespace locator

#endif  // LOCATOR_SERVER_CONFIG_HTTP_FLAGS_H_
