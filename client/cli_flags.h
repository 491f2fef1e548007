// The `locator` command line, parsed without running anything: flags (a
// FlagSet, common/flags: long only, anywhere on the line, so that "locate
// -0.5 2" keeps its negative coordinate), the command and its arguments,
// and the checks that need no server.
//
// Thread-safety: stateless functions.

#ifndef LOCATOR_CLIENT_CLI_FLAGS_H_
#define LOCATOR_CLIENT_CLI_FLAGS_H_

#include <chrono>
#include <string>
#include <string_view>

#include "client/cli_commands.h"
#include "common/channel_options.h"
#include "locator/status.h"

namespace locator {

// One command of the CLI.
using CliCommand = int (*)(LocatorClient& client, const CliSettings& settings,
                           const CliArgs& args);

// RunLocate for "locate", ... RunHealth for "health"; null for anything else.
CliCommand FindCliCommand(std::string_view name);

// What a command line asks for.
struct CliLine {
  bool help = false;  // --help: print settings.usage, nothing else
  CliCommand command = nullptr;
  CliArgs args;  // the command's arguments
  CliSettings settings;
  ChannelOptions channel;  // its security is loaded later, from `security`
  // --route: locate and batch go straight to the shards (GetTopology).
  bool route = false;
  ChannelSecurityFlags security;
  // --dataset, --crs and --interpolation.
  RequestScope scope;
  // Of every call: --deadline-ms, or kLongCallDeadline for `reload` and
  // `grid` by default.
  std::chrono::milliseconds deadline{5000};
};

// The default deadline of `reload` and `grid`: building a triangulation of
// tens of millions of points, or rendering a large raster, takes minutes.
inline constexpr std::chrono::minutes kLongCallDeadline{10};

// Parses `argc`/`argv` into `line` (settings.usage is set even on failure).
// InvalidArgument with the problem: the flag parser's message (a bad value,
// e.g. "--deadline-ms '0': must be a whole number >= 1", a bad --line or
// --interpolation), "no command", "unknown command 'X'", "--FLAG is for
// COMMANDS only" for a flag the command does not take; for `profile` a
// missing --line and --json with --csv; for `grid` a missing --out,
// --outsize and --tr both or neither, a bad --outsize, --tr, --te or
// --a_nodata, and a --of or --co that gis::CheckRasterFormat rejects.
Status ParseCliLine(int argc, const char* const* argv, CliLine* line);

}  // namespace locator

#endif  // LOCATOR_CLIENT_CLI_FLAGS_H_
