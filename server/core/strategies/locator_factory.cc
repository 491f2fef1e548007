#include "server/core/strategies/locator_factory.h"

#include "common/status_macros.h"
#include "server/core/strategies/adaptive_paper_locator.h"
#include "server/core/strategies/jump_and_walk_locator.h"
#include "server/core/strategies/self_tuning_locator.h"
#include "server/core/strategies/walk_locator.h"

namespace locator {

StatusOr<std::unique_ptr<PointLocator>> MakePointLocator(
    std::string_view name, const ServingMesh& mesh,
    const TuningOptions& options) {
  RETURN_IF_ERROR(ValidateStrategy(name));
  RETURN_IF_ERROR(ValidateTuningOptions(options));
  if (name == "walk") return std::make_unique<WalkLocator>(mesh);
  if (name == "jump-and-walk")
    return std::make_unique<JumpAndWalkLocator>(mesh);
  if (name == "adaptive-paper") {
    return std::make_unique<AdaptivePaperLocator>(mesh, options);
  }
  return std::make_unique<SelfTuningLocator>(mesh, options);
}

}  // namespace locator
