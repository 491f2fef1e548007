// locator-noop-server: locator.v1.Locator without geometry, plus the
// locator.bench.v1.NestedBatch encoding comparison. The load driver measures
// it as the ceiling the real server's throughput is compared against. Same
// serving flags, listening line, health and shutdown as locatord.

#include <memory>
#include <optional>
#include <string>

#include "server/bench/noop/noop_services.h"
#include "server/server_config.h"
#include "server/server_runner.h"

namespace locator {
namespace {

constexpr char kProgram[] = "locator-noop-server";

int Main(int argc, char** argv) {
  ServingConfig config;
  std::string help;
  const Status parsed = ParseNoopServerConfig(argc, argv, &config, &help);
  if (std::optional<int> exit_code = ExitCodeForFlags(kProgram, parsed, help)) {
    return *exit_code;
  }

  NoopLocatorService locator_service(config);
  NoopNestedBatchService nested_batch_service;
  const std::unique_ptr<ServerRunner> runner = ServerRunner::StartOrExit(
      kProgram, config, {&locator_service, &nested_batch_service});
  runner->SetServing(true);
  runner->RunAndExit();
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) { return locator::Main(argc, argv); }
