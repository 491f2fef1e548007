// Strategy "adaptive-paper": the paper's Adaptive Jump&Walk, faithfully.
//
// The first `warmup_queries` queries are answered by jump-and-walk and
// counted in a grid_size x grid_size histogram over the bounding box. The
// query that completes the warm-up finds the hot cells, merges them into
// rectangles (Section IV) and samples `samples_per_region` random edges from
// a slightly fatter copy of each (Section III). From then on a query inside
// a hot rectangle scans every sample for the closest edge midpoint and walks
// from there; any other query falls back to jump-and-walk. The paper tunes
// once; so does this strategy (Retune() re-samples from the histogram).
//
// Thread-safety: Locate() from any thread. The samples are an immutable
// snapshot published through a SnapshotSlot; the warm-up histogram
// uses relaxed per-thread counters.

#ifndef LOCATOR_CORE_ADAPTIVE_PAPER_LOCATOR_H_
#define LOCATOR_CORE_ADAPTIVE_PAPER_LOCATOR_H_

#include <atomic>
#include <memory>
#include <vector>

#include "common/mutex.h"
#include "locator/tuning_options.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/jump_and_walk_locator.h"
#include "server/core/strategies/point_locator.h"
#include "server/core/tuning/query_histogram.h"
#include "server/core/tuning/snapshot_slot.h"

namespace locator {

class AdaptivePaperLocator : public PointLocator {
 public:
  // `mesh` must outlive the locator.
  AdaptivePaperLocator(const ServingMesh& mesh, const TuningOptions& options);

  void Locate(const Point2& q, LocateResult* result,
              Detail detail = Detail::kFull) const override;
  std::string_view name() const override { return "adaptive-paper"; }
  TuningSummary Summary() const override;
  void Retune() override EXCLUDES(tune_mu_);

 private:
  struct Samples {
    uint64_t version = 0;
    std::vector<double> histogram;     // the warm-up counts
    std::vector<BoundingBox> regions;  // hot rectangles
    std::vector<BoundingBox> fat;      // the fatter copies sampled from
    std::vector<Point2> points;        // sample edge midpoints
    std::vector<uint32_t> faces;       // parallel to points
  };

  // Builds and publishes samples from the histogram counted so far.
  void Tune() const EXCLUDES(tune_mu_);
  void SampleRegion(const BoundingBox& fat, Samples* out) const;

  const ServingMesh& mesh_;
  const TuningOptions options_;
  JumpAndWalkLocator fallback_;
  mutable QueryHistogram histogram_;
  mutable std::atomic<uint64_t> warmup_seen_{0};
  mutable Mutex tune_mu_;  // serialises Tune(); never held by Locate()
  mutable std::vector<double> counts_ GUARDED_BY(tune_mu_);
  mutable SnapshotSlot<Samples> samples_;  // published by Tune()
};

}  // namespace locator

#endif  // LOCATOR_CORE_ADAPTIVE_PAPER_LOCATOR_H_
