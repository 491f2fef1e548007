// locator: command-line client of a locator.v1.Locator server.
//
//   locator [--target HOST:PORT] [--deadline-ms N] [--dataset NAME]
//           [--json] [--retry] [--token-file F] [--tls-ca F ...]
//           [command flags] COMMAND [ARGS]
//
// Flags may stand anywhere on the line (see client/cli_flags.h). Exit codes
// are documented in client/cli_commands.h.

#include <iostream>

#include "client/cli_commands.h"
#include "client/cli_flags.h"
#include "client/locator_client.h"
#include "common/grpc_lifetime.h"

namespace locator {
namespace {

int Main(int argc, char** argv) {
  CliLine line;
  if (Status parsed = ParseCliLine(argc, argv, &line); !parsed.ok()) {
    return ReportUsageError(line.settings, parsed.message());
  }
  if (line.help) {
    std::cout << line.settings.usage;
    return kExitOk;
  }
  if (Status loaded =
          LoadChannelSecurity(line.security, &line.channel.security);
      !loaded.ok()) {
    return ReportInputError(loaded.message());
  }
  LocatorClient client(CreateLocatorChannel(line.channel), line.deadline,
                       line.scope);
  if (line.route) {
    if (grpc::Status routed = client.RouteByTopology(line.channel);
        !routed.ok()) {
      return ReportRpcError(routed);
    }
  }
  return line.command(client, line.settings, line.args);
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) {
  // Outlives every gRPC object Main() makes (see grpc_lifetime.h).
  const locator::GrpcLifetime grpc;
  return locator::Main(argc, argv);
}
