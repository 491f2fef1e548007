#include "client/cli_flags.h"

#include <algorithm>
#include <limits>

#include "client/cli_flag_values.h"
#include "client/polyline_text.h"
#include "common/flags/flag_set.h"
#include "common/status_macros.h"

namespace locator {
namespace {

constexpr char kUsage[] =
    R"(usage: locator [flags] COMMAND [ARGS]

commands:
  locate X Y     the triangle that contains (X, Y): type, triangle id,
                 vertices, barycentric coordinates, value and cost
  batch FILE     locate every point of FILE (x,y rows, CSV or whitespace,
                 optional header, # comments); writes the CSV
                 x,y,type,triangle_id,v0,v1,v2,b0,b1,b2,value,cost
  stats          dataset, strategy, serving and tuning statistics
  retune         re-tune the server now; prints the new tuning
  reload [SPEC]  make the server load SPEC (a dataset file path or generator
                 spec, as locatord's --dataset takes it; default: the
                 dataset's own, read again) into --dataset and serve it;
                 waits until it serves (up to 10 minutes unless --deadline-ms
                 says otherwise) and prints the new dataset, generation and
                 tuning
  health         SERVING or NOT_SERVING; exit code 0 only when SERVING
  datasets       the server's datasets: name, default (*), serving, points,
                 triangles, CRS
  profile        the surface along --line: its exact breakpoints (distance,
                 x, y, z, triangle, kind), --samples evenly spaced points
                 and the gaps outside the hull or the domain; as text,
                 --json or --csv
  grid           render the surface to a raster file (--out) through GDAL:
                 --te XMIN YMIN XMAX YMAX (default: the dataset's bounding
                 box), --outsize WIDTH HEIGHT or --tr XRES YRES, --a_nodata,
                 --of GTiff|COG, --co NAME=VALUE; up to 10 minutes unless
                 --deadline-ms says otherwise; prints a one-line summary

exit codes: 0 ok, 1 RPC error (or not SERVING), 2 usage error (or a file
that cannot be read or written)
)";

// The commands that take each command-specific flag.
struct FlagCommands {
  std::string_view flag;
  std::vector<std::string_view> commands;
};

const std::vector<FlagCommands>& CommandFlags() {
  static const std::vector<FlagCommands> kFlags = {
      {"dataset",
       {"locate", "batch", "stats", "retune", "reload", "profile", "grid"}},
      {"crs", {"locate", "batch", "profile"}},
      {"interpolation", {"locate", "batch", "profile", "grid"}},
      {"json",
       {"locate", "stats", "retune", "reload", "health", "datasets",
        "profile"}},
      {"chunk", {"batch"}},
      {"line", {"profile"}},
      {"samples", {"profile"}},
      {"csv", {"profile"}},
      {"te", {"grid"}},
      {"outsize", {"grid"}},
      {"tr", {"grid"}},
      {"a_nodata", {"grid"}},
      {"nodata", {"grid"}},
      {"of", {"grid"}},
      {"co", {"grid"}},
      {"out", {"grid"}},
  };
  return kFlags;
}

// "a", "a and b", "a, b and c".
std::string JoinNames(const std::vector<std::string_view>& names) {
  std::string joined;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) joined += i + 1 == names.size() ? " and " : ", ";
    joined += names[i];
  }
  return joined;
}

// The flags whose values ParseCliLine checks once the command is known.
struct GridValues {
  GridFlagWords words;
  std::string a_nodata;  // into words.a_nodata when given
  std::string nodata;    // into words.nodata when given
};

// The profile command's flags: --line is required, --json and --csv
// exclusive.
Status CheckProfileFlags(const FlagSet& flags, const CliSettings& settings) {
  if (!flags.Given("line")) {
    return Status::InvalidArgument("profile needs --line");
  }
  if (settings.json && settings.csv) {
    return Status::InvalidArgument("give --json or --csv, not both");
  }
  return Status::OK();
}

// InvalidArgument for a command-specific flag given to another command.
Status CheckFlagsFitCommand(const std::string& command, const FlagSet& flags) {
  for (const FlagCommands& flag : CommandFlags()) {
    if (!flags.Given(flag.flag)) continue;
    if (std::find(flag.commands.begin(), flag.commands.end(), command) !=
        flag.commands.end()) {
      continue;
    }
    return Status::InvalidArgument("--" + std::string(flag.flag) + " is for " +
                                   JoinNames(flag.commands) + " only");
  }
  return Status::OK();
}

// Declares every flag of the CLI on `flags`, into `line`, `deadline_ms` and
// `grid`.
void AddCliFlags(CliLine* line, int64_t* deadline_ms, GridValues* grid,
                 FlagSet* flags) {
  CliSettings& settings = line->settings;
  flags->Add("target", flag::Text(&line->channel.target).Shape("HOST:PORT"),
             "server address");
  flags->Add("deadline-ms", flag::Count(deadline_ms, 1, flag::kMaxOf<int64_t>),
             "deadline of every call, in milliseconds (reload and grid: 10 "
             "minutes unless given)");
  flags->Add("json", flag::Switch(&settings.json),
             "print one JSON object (locate, stats, retune, reload, health, "
             "datasets, profile)");
  flags->Add("retry", flag::Switch(&line->channel.retry_unavailable),
             "retry calls that fail with UNAVAILABLE, with backoff");
  flags->Add("route", flag::Switch(&line->route),
             "locate and batch: send the points straight to the shards of a "
             "tiled dataset, by GetTopology of --target (a router), a batch "
             "split by shard and merged in order");
  flags->Add("dataset", flag::Text(&line->scope.dataset).Shape("NAME"),
             "all but health and datasets: the server's dataset to query, or "
             "to reload (default: its default dataset)");
  flags->Add("crs", flag::Text(&line->scope.crs).Shape("CRS"),
             "locate, batch, profile: the CRS of the points (EPSG:4326, WKT or "
             "a PROJ string; x = longitude/easting); default: the dataset's "
             "own coordinates");
  flags->Add(
      "interpolation",
      flag::Choice(&line->scope.interpolation,
                   {{"linear", v1::INTERPOLATION_LINEAR},
                    {"natural-neighbor", v1::INTERPOLATION_NATURAL_NEIGHBOR},
                    {"nearest", v1::INTERPOLATION_NEAREST}}),
      "locate, batch, profile, grid: how values are interpolated "
      "(default: linear)");
  flags->Add("chunk", flag::Count(&settings.chunk, 1, flag::kMaxOf<int64_t>),
             "points per LocateBatch call of `batch`");
  flags->Add("line", flag::Parsed([&settings](std::string_view text) {
                       return ParsePolyline(text, &settings.profile.line);
                     }).Shape("LINE"),
             "profile: the polyline, \"x0,y0 x1,y1 ...\" or WKT \"LINESTRING "
             "(x0 y0, x1 y1, ...)\"");
  flags->Add("samples",
             flag::Count(&settings.profile.samples, 0,
                         std::numeric_limits<uint32_t>::max()),
             "profile: also N evenly spaced points along the line");
  flags->Add("csv", flag::Switch(&settings.csv),
             "profile: print CSV (kind,distance,x,y,z,triangle_id,segment)");
  flags->Add("te", flag::Words(&grid->words.te, 4).Shape("XMIN YMIN XMAX YMAX"),
             "grid: the raster's outer edges, in the dataset's CRS (default: "
             "the dataset's bounding box)");
  flags->Add("outsize", flag::Words(&grid->words.outsize, 2).Shape("W H"),
             "grid: columns and rows");
  flags->Add("tr", flag::Words(&grid->words.tr, 2).Shape("XRES YRES"),
             "grid: the cell size instead (square: XRES = YRES); the box grows "
             "east and south to whole cells");
  flags->Add("a_nodata", flag::Text(&grid->a_nodata).Shape("VALUE"),
             "grid: the value of cells without one (default NaN)");
  flags->Add("nodata", flag::Text(&grid->nodata).Shape("VALUE"),
             "grid: the same as --a_nodata");
  flags->Add("of", flag::Text(&settings.grid.format.driver).Shape("FORMAT"),
             "grid: COG (Cloud-Optimized GeoTIFF; the default where GDAL has "
             "the COG driver) or GTiff (tiled 256x256)");
  flags->Add("co", flag::Repeated(&grid->words.co).Shape("NAME=VALUE"),
             "grid: a creation option of the format's GDAL driver, repeatable "
             "(e.g. COMPRESS=DEFLATE)");
  flags->Add("out", flag::Text(&settings.grid.out).Shape("FILE"),
             "grid: the raster file to write");
  AddChannelSecurityFlags(&line->security, flags);
}

}  // namespace

CliCommand FindCliCommand(std::string_view name) {
  if (name == "locate") return RunLocate;
  if (name == "batch") return RunBatch;
  if (name == "stats") return RunStats;
  if (name == "retune") return RunRetune;
  if (name == "reload") return RunReload;
  if (name == "health") return RunHealth;
  if (name == "datasets") return RunDatasets;
  if (name == "profile") return RunProfile;
  if (name == "grid") return RunGrid;
  return nullptr;
}

Status ParseCliLine(int argc, const char* const* argv, CliLine* line) {
  int64_t deadline_ms = line->deadline.count();
  GridValues grid;
  CliArgs words;  // the command, then its arguments
  FlagSet flags(kUsage);
  AddCliFlags(line, &deadline_ms, &grid, &flags);
  flags.AllowPositionals(&words);
  line->settings.usage = flags.Help();
  RETURN_IF_ERROR(flags.Parse(argc, argv));
  if (flags.help_requested()) {
    line->help = true;
    return Status::OK();
  }

  line->command = words.empty() ? nullptr : FindCliCommand(words.front());
  if (words.empty()) return Status::InvalidArgument("no command");
  if (line->command == nullptr) {
    return Status::InvalidArgument("unknown command '" + words.front() + "'");
  }
  if (Status status = CheckFlagsFitCommand(words.front(), flags);
      !status.ok()) {
    return status;
  }
  if (line->command == RunProfile) {
    if (Status status = CheckProfileFlags(flags, line->settings);
        !status.ok()) {
      return status;
    }
  }
  if (line->command == RunGrid) {
    if (flags.Given("a_nodata")) grid.words.a_nodata = grid.a_nodata;
    if (flags.Given("nodata")) grid.words.nodata = grid.nodata;
    if (Status status = ParseGridFlags(grid.words, &line->settings.grid);
        !status.ok()) {
      return status;
    }
  }
  line->deadline = std::chrono::milliseconds(deadline_ms);
  // A reload waits for a whole triangulation to be built; a grid for a
  // whole raster.
  if ((line->command == RunReload || line->command == RunGrid) &&
      !flags.Given("deadline-ms")) {
    line->deadline = kLongCallDeadline;
  }
  line->args.assign(words.begin() + 1, words.end());
  return Status::OK();
}

}  // namespace locator
