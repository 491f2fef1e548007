#include "server/core/strategies/locator_factory.h"

#include "server/core/strategies/adaptive_paper_locator.h"
#include "server/core/strategies/jump_and_walk_locator.h"
#include "server/core/strategies/self_tuning_locator.h"
#include "server/core/strategies/walk_locator.h"

namespace locator {

Status MakePointLocator(std::string_view name, const ServingMesh& mesh,
                        const TuningOptions& options,
                        std::unique_ptr<PointLocator>* out) {
  Status s = ValidateStrategy(name);
  if (s.ok()) s = ValidateTuningOptions(options);
  if (!s.ok()) return s;
  if (name == "walk") {
    *out = std::make_unique<WalkLocator>(mesh);
  } else if (name == "jump-and-walk") {
    *out = std::make_unique<JumpAndWalkLocator>(mesh);
  } else if (name == "adaptive-paper") {
    *out = std::make_unique<AdaptivePaperLocator>(mesh, options);
  } else {
    *out = std::make_unique<SelfTuningLocator>(mesh, options);
  }
  return Status::OK();
}

}  // namespace locator
