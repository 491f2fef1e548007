#include "client/cli_flags.h"

#include <algorithm>
#include <boost/program_options.hpp>
#include <limits>
#include <sstream>

#include "client/cli_flag_values.h"
#include "client/polyline_text.h"

namespace po = boost::program_options;

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

// A flag that takes exactly `count` values, e.g. --te XMIN YMIN XMAX YMAX.
// Values may be negative numbers: short flags are off, so "-10" is a value.
class FixedTokens : public po::typed_value<std::vector<std::string>> {
 public:
  FixedTokens(std::vector<std::string>* store, unsigned count)
      : po::typed_value<std::vector<std::string>>(store), count_(count) {}
  unsigned min_tokens() const override { return count_; }
  unsigned max_tokens() const override { return count_; }

 private:
  const unsigned count_;
};

// The flags as parsed, before they are checked and converted.
struct RawFlags {
  int64_t deadline_ms = 0;
  int64_t chunk = 0;
  int64_t samples = 0;
  std::string interpolation;
  std::string line;
  GridFlagWords grid;
  std::string a_nodata;  // into grid.a_nodata when given
  std::string nodata;    // into grid.nodata when given
};

// The profile command's flags into settings->profile.
Status ParseProfileFlags(const RawFlags& raw, const po::variables_map& parsed,
                         CliSettings* settings) {
  if (!parsed.count("line")) {
    return Status::InvalidArgument("profile needs --line");
  }
  if (Status status = ParsePolyline(raw.line, &settings->profile.line);
      !status.ok()) {
    return Status::InvalidArgument("--line: " + status.message());
  }
  if (raw.samples < 0 || raw.samples > std::numeric_limits<uint32_t>::max()) {
    return Status::InvalidArgument("--samples must be from 0 to 4294967295");
  }
  settings->profile.samples = static_cast<uint32_t>(raw.samples);
  if (settings->json && settings->csv) {
    return Status::InvalidArgument("give --json or --csv, not both");
  }
  return Status::OK();
}

// InvalidArgument for a command-specific flag given to another command.
Status CheckFlagsFitCommand(const std::string& command,
                            const po::variables_map& parsed) {
  for (const FlagCommands& flag : CommandFlags()) {
    const std::string name(flag.flag);
    if (!parsed.count(name) || parsed[name].defaulted()) continue;
    if (std::find(flag.commands.begin(), flag.commands.end(), command) !=
        flag.commands.end()) {
      continue;
    }
    return Status::InvalidArgument("--" + name + " is for " +
                                   JoinNames(flag.commands) + " only");
  }
  return Status::OK();
}

po::options_description Flags(CliLine* line, RawFlags* raw) {
  po::options_description flags("flags");
  flags.add_options()              //
      ("help", "print this help")  //
      ("target",
       po::value(&line->channel.target)->default_value(line->channel.target),
       "server address HOST:PORT")  //
      ("deadline-ms",
       po::value(&raw->deadline_ms)->default_value(raw->deadline_ms),
       "deadline of every call, in milliseconds")  //
      ("json", po::bool_switch(&line->settings.json),
       "print one JSON object (locate, stats, retune, reload, health, "
       "datasets, profile)")  //
      ("retry", po::bool_switch(&line->channel.retry_unavailable),
       "retry calls that fail with UNAVAILABLE, with backoff")  //
      ("dataset", po::value(&line->scope.dataset)->value_name("NAME"),
       "the server's dataset to query (default: its default dataset)")  //
      ("crs", po::value(&line->scope.crs)->value_name("CRS"),
       "locate, batch, profile: the CRS of the points (EPSG:4326, WKT or a "
       "PROJ string; x = longitude/easting); default: the dataset's own "
       "coordinates")  //
      ("interpolation", po::value(&raw->interpolation)->value_name("METHOD"),
       "locate, batch, profile, grid: linear (default), natural-neighbor or "
       "nearest")  //
      ("chunk", po::value(&raw->chunk)->default_value(raw->chunk),
       "points per LocateBatch call of `batch`")  //
      ("line", po::value(&raw->line)->value_name("LINE"),
       "profile: the polyline, \"x0,y0 x1,y1 ...\" or WKT \"LINESTRING (x0 "
       "y0, x1 y1, ...)\"")  //
      ("samples", po::value(&raw->samples)->value_name("N"),
       "profile: also N evenly spaced points along the line")  //
      ("csv", po::bool_switch(&line->settings.csv),
       "profile: print CSV (kind,distance,x,y,z,triangle_id,segment)")  //
      ("te",
       (new FixedTokens(&raw->grid.te, 4))->value_name("XMIN YMIN XMAX YMAX"),
       "grid: the raster's outer edges, in the dataset's CRS (default: the "
       "dataset's bounding box)")  //
      ("outsize", (new FixedTokens(&raw->grid.outsize, 2))->value_name("W H"),
       "grid: columns and rows")  //
      ("tr", (new FixedTokens(&raw->grid.tr, 2))->value_name("XRES YRES"),
       "grid: the cell size instead (square: XRES = YRES); the box grows "
       "east and south to whole cells")  //
      ("a_nodata", po::value(&raw->a_nodata)->value_name("VALUE"),
       "grid: the value of cells without one (default NaN)")  //
      ("nodata", po::value(&raw->nodata)->value_name("VALUE"),
       "grid: the same as --a_nodata")  //
      ("of",
       po::value(&line->settings.grid.format.driver)->value_name("FORMAT"),
       "grid: COG (Cloud-Optimized GeoTIFF; the default where GDAL has the "
       "COG driver) or GTiff (tiled 256x256)")  //
      ("co", po::value(&raw->grid.co)->composing()->value_name("NAME=VALUE"),
       "grid: a creation option of the format's GDAL driver, repeatable "
       "(e.g. COMPRESS=DEFLATE)")  //
      ("out", po::value(&line->settings.grid.out)->value_name("FILE"),
       "grid: the raster file to write");
  AddChannelSecurityFlags(&line->security, &flags);
  return flags;
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
  RawFlags raw;
  raw.deadline_ms = line->deadline.count();
  raw.chunk = static_cast<int64_t>(line->settings.chunk);
  CliArgs words;  // the command, then its arguments

  const po::options_description flags = Flags(line, &raw);
  po::options_description all;
  all.add(flags).add_options()("words", po::value(&words));
  po::positional_options_description positional;
  positional.add("words", -1);

  std::ostringstream usage;
  usage << kUsage << flags;
  line->settings.usage = usage.str();
  po::variables_map parsed;
  try {
    // No short flags: "-1.5" must stay a positional number.
    const auto style = po::command_line_style::unix_style ^
                       po::command_line_style::allow_short ^
                       po::command_line_style::allow_guessing;
    po::store(po::command_line_parser(argc, argv)
                  .options(all)
                  .positional(positional)
                  .style(style)
                  .run(),
              parsed);
    po::notify(parsed);
  } catch (const po::error& error) {
    return Status::InvalidArgument(error.what());
  }
  if (parsed.count("help")) {
    line->help = true;
    return Status::OK();
  }

  line->command = words.empty() ? nullptr : FindCliCommand(words.front());
  if (words.empty()) return Status::InvalidArgument("no command");
  if (line->command == nullptr) {
    return Status::InvalidArgument("unknown command '" + words.front() + "'");
  }
  if (Status status = CheckFlagsFitCommand(words.front(), parsed);
      !status.ok()) {
    return status;
  }
  if (raw.deadline_ms <= 0) {
    return Status::InvalidArgument("--deadline-ms must be positive");
  }
  if (raw.chunk <= 0)
    return Status::InvalidArgument("--chunk must be positive");
  if (parsed.count("interpolation")) {
    if (Status status =
            ParseInterpolation(raw.interpolation, &line->scope.interpolation);
        !status.ok()) {
      return status;
    }
  }
  if (line->command == RunProfile) {
    if (Status status = ParseProfileFlags(raw, parsed, &line->settings);
        !status.ok()) {
      return status;
    }
  }
  if (line->command == RunGrid) {
    if (parsed.count("a_nodata")) raw.grid.a_nodata = raw.a_nodata;
    if (parsed.count("nodata")) raw.grid.nodata = raw.nodata;
    if (Status status = ParseGridFlags(raw.grid, &line->settings.grid);
        !status.ok()) {
      return status;
    }
  }
  line->settings.chunk = static_cast<size_t>(raw.chunk);
  line->deadline = std::chrono::milliseconds(raw.deadline_ms);
  // A reload waits for a whole triangulation to be built; a grid for a
  // whole raster.
  if ((line->command == RunReload || line->command == RunGrid) &&
      parsed["deadline-ms"].defaulted()) {
    line->deadline = kLongCallDeadline;
  }
  line->args.assign(words.begin() + 1, words.end());
  return Status::OK();
}

}  // namespace locator
