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

#include "common/geometry.h"
#include "common/status.h"
#include "server/core/locate_result.h"

namespace locator {

// How a strategy's learned state persists across restarts (self-tuning
// with TuningOptions::state_dir).
struct PersistenceSummary {
  // The state file; empty when nothing persists.
  std::string state_path;
  // Whether the tuning was restored from it when the strategy was built.
  bool restored_from_state = false;
  // Why an existing state file was not used; empty otherwise.
  std::string load_error;
  // State files written so far, and why the last write failed ("" if it
  // did not).
  uint64_t saves = 0;
  std::string save_error;
};

// What a strategy has learned, for GetStats and the status page.
struct TuningSummary {
  // Monotonic version of the published snapshot (0: none published yet).
  uint64_t snapshot_version = 0;
  uint64_t retune_count = 0;
  // The query histogram: grid_size x grid_size cells over grid_box, row-major
  // from (min_x, min_y); counts are decayed for self-tuning. Empty when the
  // strategy keeps none.
  int grid_size = 0;
  BoundingBox grid_box;
  std::vector<double> histogram;
  // Rectangles where queries concentrate.
  std::vector<BoundingBox> hot_regions;
  // A sample of the start points in use (at most a few thousand).
  std::vector<Point2> start_points;
  // Total number of start points in use.
  uint64_t start_point_count = 0;
  // Bytes of the tuning structures (the published snapshot).
  size_t memory_bytes = 0;
  PersistenceSummary persistence;
  // Queries answered since the strategy was created in cells it had tuned
  // for (hot) and elsewhere (fallback). Self-tuning only; 0 for the others.
  uint64_t hot_queries = 0;
  uint64_t fallback_queries = 0;
  // Self-tuning only: wall-clock ns spent re-tuning (inline in queries or on
  // the tuner thread), and the most table-building work (StartTable::Builder
  // units) one located query paid for inline.
  uint64_t tune_nanos = 0;
  uint64_t max_tune_units_per_query = 0;
};

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
