#include "common/gis/crs_verdicts.h"

#include <utility>

namespace locator::gis {

Status CrsVerdicts::Decide(const std::string& key,
                           const std::function<Status()>& make) {
  std::shared_ptr<Verdict> verdict;
  {
    MutexLock lock(&mu_);
    if (const auto it = verdicts_.find(key); it != verdicts_.end()) {
      verdict = it->second;
      while (!verdict->decided) decided_.Wait(&mu_);
      if (!verdict->status.ok()) return verdict->status;
      verdict = nullptr;  // known good: made below, not recorded again
    } else {
      if (verdicts_.size() >= kCapacity) {
        std::erase_if(verdicts_,
                      [](const auto& entry) { return entry.second->decided; });
      }
      verdict = std::make_shared<Verdict>();
      verdicts_.emplace(key, verdict);
    }
  }
  const Status status = make();
  if (verdict != nullptr) {
    {
      MutexLock lock(&mu_);
      verdict->status = status;
      verdict->decided = true;
    }
    decided_.SignalAll();
  }
  return status;
}

}  // namespace locator::gis
