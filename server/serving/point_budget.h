// PointBudget: locatord's --max-dataset-points as a total over all of its
// datasets.
//
// A dataset holds the points of the dataset its engine serves and, while a
// build of it runs, those of the build too (both engines are in memory
// until the new one is published): its holding is the larger of the two.
// A build of dataset i may read at most Available(i), the total less what
// the other datasets hold; once it has read n points, Claim(i, n) reserves
// them if that still fits (another dataset's build may have claimed
// meanwhile), before anything is triangulated. The build then ends with
// Commit(i) (its engine serves: n is now what i serves) or Cancel(i).
//
// Owns the counts. Thread-safety: all methods may be called concurrently;
// builds of one dataset must not overlap (EngineReloader ensures it).

#ifndef LOCATOR_SERVER_POINT_BUDGET_H_
#define LOCATOR_SERVER_POINT_BUDGET_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/mutex.h"
#include "locator/status.h"

namespace locator {

class PointBudget {
 public:
  // `total` points shared by `datasets` datasets, none held yet.
  PointBudget(uint64_t total, size_t datasets);

  uint64_t total() const { return total_; }

  // The points a build of `dataset` may read: the total less what the
  // others hold.
  uint64_t Available(size_t dataset) const EXCLUDES(mu_);
  // The points the datasets other than `dataset` hold.
  uint64_t HeldByOthers(size_t dataset) const EXCLUDES(mu_);
  // The points all datasets hold (never above the total).
  uint64_t Held() const EXCLUDES(mu_);

  // Reserves `points` for a build of `dataset` if they fit beside what the
  // others hold; ResourceExhausted naming the figures otherwise (nothing
  // changes).
  Status Claim(size_t dataset, uint64_t points) EXCLUDES(mu_);
  // The build of `dataset` serves now: its claim replaces what it served.
  void Commit(size_t dataset) EXCLUDES(mu_);
  // The build of `dataset` failed: its claim is dropped.
  void Cancel(size_t dataset) EXCLUDES(mu_);

 private:
  struct Holding {
    uint64_t serving = 0;
    uint64_t building = 0;
    uint64_t held() const { return serving > building ? serving : building; }
  };

  uint64_t HeldByOthersLocked(size_t dataset) const REQUIRES(mu_);

  const uint64_t total_;
  mutable Mutex mu_;
  std::vector<Holding> holdings_ GUARDED_BY(mu_);
};

}  // namespace locator

#endif  // LOCATOR_SERVER_POINT_BUDGET_H_
