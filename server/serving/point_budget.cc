#include "server/serving/point_budget.h"

#include <string>

namespace locator {

PointBudget::PointBudget(uint64_t total, size_t datasets)
    : total_(total), holdings_(datasets) {}

uint64_t PointBudget::HeldByOthersLocked(size_t dataset) const {
  uint64_t others = 0;
  for (size_t i = 0; i < holdings_.size(); ++i) {
    if (i != dataset) others += holdings_[i].held();
  }
  return others;
}

uint64_t PointBudget::HeldByOthers(size_t dataset) const {
  MutexLock lock(&mu_);
  return HeldByOthersLocked(dataset);
}

uint64_t PointBudget::Held() const {
  MutexLock lock(&mu_);
  // Others than a dataset that does not exist: all of them.
  return HeldByOthersLocked(holdings_.size());
}

uint64_t PointBudget::Available(size_t dataset) const {
  const uint64_t others = HeldByOthers(dataset);
  return others >= total_ ? 0 : total_ - others;
}

Status PointBudget::Claim(size_t dataset, uint64_t points) {
  MutexLock lock(&mu_);
  const uint64_t others = HeldByOthersLocked(dataset);
  if (others > total_ || points > total_ - others) {
    return Status::ResourceExhausted(std::to_string(points) +
                                     " points would take the datasets' total "
                                     "beyond " +
                                     std::to_string(total_) +
                                     " (the other datasets hold " +
                                     std::to_string(others) + ")");
  }
  holdings_[dataset].building = points;
  return Status::OK();
}

void PointBudget::Commit(size_t dataset) {
  MutexLock lock(&mu_);
  Holding& holding = holdings_[dataset];
  holding.serving = holding.building;
  holding.building = 0;
}

void PointBudget::Cancel(size_t dataset) {
  MutexLock lock(&mu_);
  holdings_[dataset].building = 0;
}

}  // namespace locator
