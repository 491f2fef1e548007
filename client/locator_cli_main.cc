// locator: command-line client of a locator.v1.Locator server.
//
//   locator [--target HOST:PORT] [--deadline-ms N] [--json] [--retry]
//           [--chunk N] [--token-file F] [--tls-ca F ...] COMMAND [ARGS]
//
// Flags may stand anywhere on the line. Only long flags exist, so a negative
// coordinate ("locate -0.5 2") is never taken for one. Exit codes are
// documented in client/cli_commands.h.

#include <boost/program_options.hpp>
#include <chrono>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "client/cli_commands.h"
#include "client/locator_client.h"

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

// The default deadline of `reload`: building a triangulation of tens of
// millions of points takes minutes.
constexpr int64_t kReloadDeadlineMs = 10 * 60 * 1000;

using Command = int (*)(LocatorClient&, const CliSettings&, const CliArgs&);

Command FindCommand(std::string_view name) {
  if (name == "locate") return RunLocate;
  if (name == "batch") return RunBatch;
  if (name == "stats") return RunStats;
  if (name == "retune") return RunRetune;
  if (name == "reload") return RunReload;
  if (name == "health") return RunHealth;
  return nullptr;
}

int Main(int argc, char** argv) {
  ChannelOptions channel;
  ChannelSecurityFlags security;
  CliSettings settings;
  int64_t deadline_ms = 5000;
  int64_t chunk = static_cast<int64_t>(settings.chunk);
  CliArgs words;  // the command, then its arguments

  po::options_description flags("flags");
  flags.add_options()              //
      ("help", "print this help")  //
      ("target", po::value(&channel.target)->default_value(channel.target),
       "server address HOST:PORT")  //
      ("deadline-ms", po::value(&deadline_ms)->default_value(deadline_ms),
       "deadline of every call, in milliseconds")  //
      ("json", po::bool_switch(&settings.json),
       "print one JSON object (locate, stats, retune, reload, health)")  //
      ("retry", po::bool_switch(&channel.retry_unavailable),
       "retry calls that fail with UNAVAILABLE, with backoff")  //
      ("chunk", po::value(&chunk)->default_value(chunk),
       "points per LocateBatch call of `batch`")  //
      ("dataset", po::value(&settings.dataset),
       "`reload`: a dataset file path or generator spec, as the server's "
       "--dataset takes it");
  AddChannelSecurityFlags(&security, &flags);
  po::options_description all;
  all.add(flags).add_options()("words", po::value(&words));
  po::positional_options_description positional;
  positional.add("words", -1);

  std::ostringstream usage;
  usage << kUsage << flags;
  settings.usage = usage.str();
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
    return ReportUsageError(settings, error.what());
  }
  if (parsed.count("help")) {
    std::cout << settings.usage;
    return kExitOk;
  }

  Command command = words.empty() ? nullptr : FindCommand(words.front());
  std::string problem;
  if (words.empty()) {
    problem = "no command";
  } else if (command == nullptr) {
    problem = "unknown command '" + words.front() + "'";
  } else if (deadline_ms <= 0) {
    problem = "--deadline-ms must be positive";
  } else if (chunk <= 0) {
    problem = "--chunk must be positive";
  } else if (parsed.count("dataset") && command != RunReload) {
    problem = "--dataset is for reload only";
  }
  if (!problem.empty()) return ReportUsageError(settings, problem);
  settings.chunk = static_cast<size_t>(chunk);
  // A reload waits for a whole triangulation to be built.
  if (command == RunReload && parsed["deadline-ms"].defaulted()) {
    deadline_ms = kReloadDeadlineMs;
  }
  if (Status loaded = LoadChannelSecurity(security, &channel.security);
      !loaded.ok()) {
    return ReportInputError(loaded.message());
  }

  LocatorClient client(CreateLocatorChannel(channel),
                       std::chrono::milliseconds(deadline_ms));
  const CliArgs args(words.begin() + 1, words.end());
  return command(client, settings, args);
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) { return locator::Main(argc, argv); }
