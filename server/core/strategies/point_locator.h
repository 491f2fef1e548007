// PointLocator: one point-location strategy over a Triangulation.
//
// Strategies (see locator_factory.h): walk, jump-and-walk, adaptive-paper and
// self-tuning (the default). All of them answer exactly what CGAL's own
// locate() answers; they differ only in where the walk starts, i.e. in cost.
//
// Thread-safety: Locate() may be called from any number of threads at once.
// Strategies that learn from traffic count queries without serialising
// readers and swap immutable tuning snapshots atomically.

#ifndef LOCATOR_CORE_POINT_LOCATOR_H_
#define LOCATOR_CORE_POINT_LOCATOR_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "locator/engine_info.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/status.h"

namespace locator {

class PointLocator {
 public:
  virtual ~PointLocator() = default;

  // Locates the finite point q, filling only `detail`. Precondition:
  // IsFinite(q) (callers validate).
  virtual void Locate(const Point2& q, LocateResult* result,
                      Detail detail = Detail::kFull) const = 0;

  // Locates queries[i] into results[i] for every i; same preconditions.
  // Strategies override it to amortise per-call work over the batch, to
  // fill only `detail`, and to start each walk from the previous answer
  // when that is nearer (callers sort batches along a space-filling curve).
  virtual void LocateMany(std::span<const Point2> queries,
                          LocateResult* results,
                          Detail detail = Detail::kFull) const {
    for (size_t i = 0; i < queries.size(); ++i) {
      Locate(queries[i], &results[i], detail);
    }
  }

  // The strategy's name as accepted by MakePointLocator().
  virtual std::string_view name() const = 0;

  // What it has learned so far.
  virtual TuningSummary Summary() const = 0;

  // Re-tunes now from the traffic seen so far (no-op for fixed strategies).
  // Returns once the new snapshot is published.
  virtual void Retune() {}

  // Writes the learned state to the strategy's state file now, if it
  // changed since the last save. OK when the strategy persists nothing.
  virtual Status SaveState() { return Status::OK(); }
};

}  // namespace locator

#endif  // LOCATOR_CORE_POINT_LOCATOR_H_
