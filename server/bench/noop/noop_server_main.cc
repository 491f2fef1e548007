// locator-noop-server: locator.v1.Locator without geometry, plus the
// locator.bench.v1.NestedBatch encoding comparison. The load driver measures
// it as the ceiling the real server's throughput is compared against. Same
// serving flags, listening line, health and shutdown as locatord.

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "common/flags/flag_set.h"
#include "server/bench/noop/noop_services.h"
#include "server/config/server_config.h"
#include "server/main/server_runner.h"

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
  std::unique_ptr<ServerRunner> runner;
  if (Status started = ServerRunner::Start(
          kProgram, config, {&locator_service, &nested_batch_service}, {},
          &runner);
      !started.ok()) {
    std::cerr << kProgram << ": " << started.message() << std::endl;
    return 1;
  }
  runner->SetServing(true);
  ExitWithoutTeardown(runner->Run());
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) { return locator::Main(argc, argv); }
