#include "client/cli_flags.h"

#include <boost/program_options.hpp>
#include <sstream>

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
  reload         make the server load --dataset SPEC (default: its own
                 --dataset, read again) and serve it; waits until it serves
                 (up to 10 minutes unless --deadline-ms says otherwise) and
                 prints the new dataset, generation and tuning
  health         SERVING or NOT_SERVING; exit code 0 only when SERVING

exit codes: 0 ok, 1 RPC error (or not SERVING), 2 usage error

)";

}  // namespace

CliCommand FindCliCommand(std::string_view name) {
  if (name == "locate") return RunLocate;
  if (name == "batch") return RunBatch;
  if (name == "stats") return RunStats;
  if (name == "retune") return RunRetune;
  if (name == "reload") return RunReload;
  if (name == "health") return RunHealth;
  return nullptr;
}

Status ParseCliLine(int argc, const char* const* argv, CliLine* line) {
  int64_t deadline_ms = line->deadline.count();
  int64_t chunk = static_cast<int64_t>(line->settings.chunk);
  CliArgs words;  // the command, then its arguments

  po::options_description flags("flags");
  flags.add_options()              //
      ("help", "print this help")  //
      ("target",
       po::value(&line->channel.target)->default_value(line->channel.target),
       "server address HOST:PORT")  //
      ("deadline-ms", po::value(&deadline_ms)->default_value(deadline_ms),
       "deadline of every call, in milliseconds")  //
      ("json", po::bool_switch(&line->settings.json),
       "print one JSON object (locate, stats, retune, reload, health)")  //
      ("retry", po::bool_switch(&line->channel.retry_unavailable),
       "retry calls that fail with UNAVAILABLE, with backoff")  //
      ("chunk", po::value(&chunk)->default_value(chunk),
       "points per LocateBatch call of `batch`")  //
      ("dataset", po::value(&line->settings.dataset),
       "`reload`: a dataset file path or generator spec, as the server's "
       "--dataset takes it");
  AddChannelSecurityFlags(&line->security, &flags);
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
  if (deadline_ms <= 0) {
    return Status::InvalidArgument("--deadline-ms must be positive");
  }
  if (chunk <= 0) return Status::InvalidArgument("--chunk must be positive");
  if (parsed.count("dataset") && line->command != RunReload) {
    return Status::InvalidArgument("--dataset is for reload only");
  }
  line->settings.chunk = static_cast<size_t>(chunk);
  line->deadline = std::chrono::milliseconds(deadline_ms);
  // A reload waits for a whole triangulation to be built.
  if (line->command == RunReload && parsed["deadline-ms"].defaulted()) {
    line->deadline = kReloadDeadline;
  }
  line->args.assign(words.begin() + 1, words.end());
  return Status::OK();
}

}  // namespace locator
