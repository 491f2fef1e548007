#include "server/core/locator_factory.h"

#include "server/core/adaptive_paper_locator.h"
#include "server/core/jump_and_walk_locator.h"
#include "server/core/self_tuning_locator.h"
#include "server/core/walk_locator.h"

namespace locator {

namespace {

// Grids above this make the per-cell arrays outgrow any sane budget.
constexpr int kMaxGridSize = 1024;

Status ValidateTuning(const TuningOptions& o) {
  if (o.grid_size < 1 || o.grid_size > kMaxGridSize) {
    return Status::InvalidArgument("grid size must be in 1.." +
                                   std::to_string(kMaxGridSize) + ", got " +
                                   std::to_string(o.grid_size));
  }
  if (o.warmup_queries < 1) {
    return Status::InvalidArgument("warm-up must be at least 1 query");
  }
  if (o.retune_every < 1) {
    return Status::InvalidArgument("re-tune interval must be at least 1 query");
  }
  if (o.samples_per_region < 1) {
    return Status::InvalidArgument("samples per region must be at least 1");
  }
  if (!(o.decay >= 0 && o.decay <= 1)) {
    return Status::InvalidArgument("decay must be in [0, 1]");
  }
  if (!(o.budget_fraction > 0 && o.budget_fraction <= 1)) {
    return Status::InvalidArgument("budget fraction must be in (0, 1]");
  }
  return Status::OK();
}

}  // namespace

const std::vector<std::string>& StrategyNames() {
  static const std::vector<std::string> kNames = {
      "walk", "jump-and-walk", "adaptive-paper", "self-tuning"};
  return kNames;
}

Status MakePointLocator(std::string_view name, const Triangulation& t,
                        const TuningOptions& options,
                        std::unique_ptr<PointLocator>* out) {
  Status s = ValidateTuning(options);
  if (!s.ok()) return s;
  if (name == "walk") {
    *out = std::make_unique<WalkLocator>(t);
  } else if (name == "jump-and-walk") {
    *out = std::make_unique<JumpAndWalkLocator>(t);
  } else if (name == "adaptive-paper") {
    *out = std::make_unique<AdaptivePaperLocator>(t, options);
  } else if (name == "self-tuning") {
    *out = std::make_unique<SelfTuningLocator>(t, options);
  } else {
    std::string valid;
    for (const std::string& n : StrategyNames()) {
      valid += (valid.empty() ? "" : ", ") + n;
    }
    return Status::InvalidArgument("unknown strategy '" + std::string(name) +
                                   "' (valid: " + valid + ")");
  }
  return Status::OK();
}

}  // namespace locator
