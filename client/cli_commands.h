// The `locator` CLI's commands. Each checks its own arguments, makes its
// call(s) and prints the answer to stdout; errors go to stderr.
//
// Exit codes (the process's, returned by every command):
//   0  success (for `health`: the server is SERVING);
//   1  an RPC failed, printed as "error: <CODE>: <message>" (for `health`:
//      also NOT_SERVING and the other non-SERVING answers);
//   2  usage: a bad command, flag or argument, a number that does not parse,
//      a points file that cannot be read or a raster file that cannot be
//      written. Values that parse are the server's to judge: `locate nan 0`
//      is sent, and INVALID_ARGUMENT comes back as exit code 1.
//
// Thread-safety: commands run on the main thread, one per process.

#ifndef LOCATOR_CLIENT_CLI_COMMANDS_H_
#define LOCATOR_CLIENT_CLI_COMMANDS_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "client/locator_client.h"
#include "common/gis/raster_writer.h"
#include "locator/geometry.h"

namespace locator {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRpcError = 1;
inline constexpr int kExitUsage = 2;

// What `profile` asks for.
struct ProfileSettings {
  // --line: the polyline's vertices, at least 2.
  std::vector<Point2> line;
  // --samples: evenly spaced points to return too.
  uint32_t samples = 0;
};

// What `grid` renders and where it writes it.
struct GridSettings {
  // --te: the raster's outer edges; none: the dataset's bounding box.
  std::optional<BoundingBox> box;
  // --outsize: columns and rows (0 when --tr gives the cell size instead).
  uint32_t width = 0;
  uint32_t height = 0;
  // --tr: the cell size (0 when --outsize gives the size).
  double cell_size = 0;
  // --a_nodata: the value of cells without one; none: the server's (NaN).
  std::optional<double> nodata;
  // --of and --co.
  gis::RasterFormat format;
  // --out: the raster file.
  std::string out;
};

struct CliSettings {
  // Print one JSON object instead of text (locate, stats, retune, reload,
  // health, datasets, profile).
  bool json = false;
  // `profile`: print a CSV table instead of text.
  bool csv = false;
  // Points per LocateBatch call of `batch`.
  size_t chunk = 10'000;
  ProfileSettings profile;
  GridSettings grid;
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
// `reload [SPEC]`.
int RunReload(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args);
// `health`.
int RunHealth(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args);
// `datasets`.
int RunDatasets(LocatorClient& client, const CliSettings& settings,
                const CliArgs& args);
// `profile --line ...`.
int RunProfile(LocatorClient& client, const CliSettings& settings,
               const CliArgs& args);
// `grid --out FILE ...`: writes the raster to FILE as the Grid stream
// arrives; prints a one-line summary.
int RunGrid(LocatorClient& client, const CliSettings& settings,
            const CliArgs& args);

// Prints "error: <CODE>: <message>"; returns kExitRpcError.
int ReportRpcError(const grpc::Status& status);
// Prints "error: <what>" and the usage; returns kExitUsage.
int ReportUsageError(const CliSettings& settings, std::string_view what);
// ReportUsageError(settings, "<command> takes no arguments") unless `args`
// is empty; true when it is.
bool TakesNoArguments(const CliSettings& settings, std::string_view command,
                      const CliArgs& args);
// Prints "error: <what>" for an unusable file (a points file that cannot be
// read or parsed, a raster that cannot be written); returns kExitUsage.
int ReportInputError(std::string_view what);

}  // namespace locator

#endif  // LOCATOR_CLIENT_CLI_COMMANDS_H_
