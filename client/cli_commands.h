// The `locator` CLI's commands. Each checks its own arguments, makes its
// call(s) and prints the answer to stdout; errors go to stderr.
//
// Exit codes (the process's, returned by every command):
//   0  success (for `health`: the server is SERVING);
//   1  an RPC failed, printed as "error: <CODE>: <message>" (for `health`:
//      also NOT_SERVING and the other non-SERVING answers);
//   2  usage: a bad command, flag or argument, a number that does not parse,
//      or a points file that cannot be read. Values that parse are the
//      server's to judge: `locate nan 0` is sent, and INVALID_ARGUMENT comes
//      back as exit code 1.
//
// Thread-safety: commands run on the main thread, one per process.

#ifndef LOCATOR_CLIENT_CLI_COMMANDS_H_
#define LOCATOR_CLIENT_CLI_COMMANDS_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "client/locator_client.h"

namespace locator {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRpcError = 1;
inline constexpr int kExitUsage = 2;

struct CliSettings {
  // Print one JSON object instead of text (locate, stats, retune, reload,
  // health).
  bool json = false;
  // Points per LocateBatch call of `batch`.
  size_t chunk = 10'000;
  // The dataset `reload` asks for ("": the server's configured one).
  std::string dataset;
  // Printed after a usage error.
  std::string usage;
};

using CliArgs = std::vector<std::string>;

// `locate X Y`.
int RunLocate(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args);
// `batch FILE`: CSV to stdout, one row per point of FILE, in order.
int RunBatch(LocatorClient& client, const CliSettings& settings,
             const CliArgs& args);
// `stats`.
int RunStats(LocatorClient& client, const CliSettings& settings,
             const CliArgs& args);
// `retune`.
int RunRetune(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args);
// `reload` (with --dataset SPEC).
int RunReload(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args);
// `health`.
int RunHealth(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args);

// Prints "error: <CODE>: <message>"; returns kExitRpcError.
int ReportRpcError(const grpc::Status& status);
// Prints "error: <what>" and the usage; returns kExitUsage.
int ReportUsageError(const CliSettings& settings, std::string_view what);
// Prints "error: <what>" for unusable input (a points file that cannot be
// read or parsed); returns kExitUsage.
int ReportInputError(std::string_view what);

}  // namespace locator

#endif  // LOCATOR_CLIENT_CLI_COMMANDS_H_
