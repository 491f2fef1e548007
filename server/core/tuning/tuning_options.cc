#include "locator/tuning_options.h"

namespace locator {

const std::vector<std::string>& StrategyNames() {
  static const std::vector<std::string> kNames = {
      "walk", "jump-and-walk", "adaptive-paper", "self-tuning"};
  return kNames;
}

Status ValidateStrategy(std::string_view name) {
  std::string valid;
  for (const std::string& n : StrategyNames()) {
    if (n == name) return Status::OK();
    valid += (valid.empty() ? "" : ", ") + n;
  }
  return Status::InvalidArgument("unknown strategy '" + std::string(name) +
                                 "' (valid: " + valid + ")");
}

Status ValidateTuningOptions(const TuningOptions& o) {
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

}  // namespace locator
