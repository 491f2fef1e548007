// RunRouter: locatord --route: serves RouterService in front of --shards
// with the serving flags (address, TLS, limits, default deadline) until
// SIGINT or SIGTERM, then drains like locatord.
//
// Thread-safety: called once, from main().

#ifndef LOCATOR_SERVER_ROUTE_ROUTER_MAIN_H_
#define LOCATOR_SERVER_ROUTE_ROUTER_MAIN_H_

#include <string_view>

#include "server/config/server_config.h"

namespace locator {

// Runs the router `config` describes and ends the process with its exit
// code (ExitWithoutTeardown: gRPC threads may still be finishing calls to
// the shards that refer to the router).
[[noreturn]] void RunRouter(std::string_view program,
                            const ServerConfig& config);

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_ROUTER_MAIN_H_
