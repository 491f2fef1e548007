#include "client/cli_commands.h"

#include <iostream>

#include "client/cli_format.h"
#include "client/health_check.h"
#include "common/text_fields.h"

namespace locator {
namespace {

// Makes `call` and prints its answer: as JSON with --json, else as
// format_text(answer).
template <typename Response, typename Call, typename FormatText>
int CallAndPrint(const CliSettings& settings, Call call,
                 FormatText format_text) {
  Response response;
  const grpc::Status status = call(&response);
  if (!status.ok()) return ReportRpcError(status);
  std::cout << (settings.json ? MessageToJson(response)
                              : format_text(response));
  return kExitOk;
}

}  // namespace

int ReportRpcError(const grpc::Status& status) {
  std::cerr << "error: " << DescribeRpcError(status) << "\n";
  return kExitRpcError;
}

int ReportUsageError(const CliSettings& settings, std::string_view what) {
  std::cerr << "error: " << what << "\n\n" << settings.usage;
  return kExitUsage;
}

bool TakesNoArguments(const CliSettings& settings, std::string_view command,
                      const CliArgs& args) {
  if (args.empty()) return true;
  ReportUsageError(settings, std::string(command) + " takes no arguments");
  return false;
}

int ReportInputError(std::string_view what) {
  std::cerr << "error: " << what << "\n";
  return kExitUsage;
}

int RunLocate(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args) {
  if (args.size() != 2) return ReportUsageError(settings, "locate takes X Y");
  Point2 point;
  if (!ParseDouble(args[0], &point.x) || !ParseDouble(args[1], &point.y)) {
    return ReportUsageError(settings, "locate: '" + args[0] + " " + args[1] +
                                          "' are not two numbers");
  }
  return CallAndPrint<v1::LocateResponse>(
      settings,
      [&](v1::LocateResponse* response) {
        return client.Locate(point, response);
      },
      FormatLocate);
}

int RunStats(LocatorClient& client, const CliSettings& settings,
             const CliArgs& args) {
  if (!TakesNoArguments(settings, "stats", args)) return kExitUsage;
  return CallAndPrint<v1::GetStatsResponse>(
      settings,
      [&](v1::GetStatsResponse* response) { return client.GetStats(response); },
      FormatStats);
}

int RunRetune(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args) {
  if (!TakesNoArguments(settings, "retune", args)) return kExitUsage;
  return CallAndPrint<v1::RetuneResponse>(
      settings,
      [&](v1::RetuneResponse* response) { return client.Retune(response); },
      [](const v1::RetuneResponse& response) {
        return FormatTuning(response.tuning());
      });
}

int RunReload(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args) {
  if (args.size() > 1) {
    return ReportUsageError(settings, "reload takes at most one SPEC");
  }
  const std::string spec = args.empty() ? "" : args[0];
  return CallAndPrint<v1::ReloadResponse>(
      settings,
      [&](v1::ReloadResponse* response) {
        return client.Reload(spec, response);
      },
      FormatReload);
}

int RunDatasets(LocatorClient& client, const CliSettings& settings,
                const CliArgs& args) {
  if (!TakesNoArguments(settings, "datasets", args)) return kExitUsage;
  return CallAndPrint<v1::ListDatasetsResponse>(
      settings,
      [&](v1::ListDatasetsResponse* response) {
        return client.ListDatasets(response);
      },
      FormatDatasets);
}

int RunProfile(LocatorClient& client, const CliSettings& settings,
               const CliArgs& args) {
  if (!TakesNoArguments(settings, "profile", args)) return kExitUsage;
  return CallAndPrint<v1::ProfileResponse>(
      settings,
      [&](v1::ProfileResponse* response) {
        return client.Profile(settings.profile.line, settings.profile.samples,
                              response);
      },
      settings.csv ? ProfileCsv : FormatProfile);
}

int RunHealth(LocatorClient& client, const CliSettings& settings,
              const CliArgs& args) {
  if (!TakesNoArguments(settings, "health", args)) return kExitUsage;
  HealthStatus health = HealthStatus::kUnknown;
  const grpc::Status status = client.CheckHealth(&health);
  if (!status.ok()) return ReportRpcError(status);
  const std::string_view name = HealthStatusName(health);
  if (settings.json) {
    std::cout << "{\"status\":\"" << name << "\"}\n";
  } else {
    std::cout << name << "\n";
  }
  return health == HealthStatus::kServing ? kExitOk : kExitRpcError;
}

}  // namespace locator
