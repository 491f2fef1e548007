// Strategy "self-tuning" (the default): the paper's adaptive idea, made
// continuous and O(1).
//
// Beyond the paper: (i) it keeps learning: queries are counted into a
// histogram that decays at every re-tune, a re-tune runs every
// `retune_every` queries, and sooner when most queries land outside the
// cells it tuned for (the hot spot moved); (ii) the jump is O(1): a query
// maps to its cell of a StartTable and starts there, instead of scanning
// every sample; (iii) starts are spent where queries land and where points
// are dense, under a memory budget (HotRegionTuner; its coarse grid is the
// largest <= grid_size that the budget affords); (iv) every cell keeps
// a start, so no traffic is answered worse than by a walk inside its cell.
//
// Thread-safety: Locate() from any number of threads. The read path loads
// the current TuningSnapshot (immutable, published through a SnapshotSlot,
// like LevelDB's Version) and counts into relaxed per-thread
// histogram shards; it never waits for the tuner. Re-tunes are serialised
// by a mutex only the tuner holds: inline in the query that triggers one
// (options.background == false, deterministic) or on a background thread.
//
// Persistence (options.state_dir set): the constructor restores the state
// stored for this dataset and configuration, if any and usable, so the
// first query is answered as tuned as the last one before a restart. The
// background tuner thread saves after a re-tune, at most once per
// kMinSaveInterval, under the tuner mutex and never on the read path;
// SaveState() saves now (a clean shutdown, a reload).

#ifndef LOCATOR_CORE_SELF_TUNING_LOCATOR_H_
#define LOCATOR_CORE_SELF_TUNING_LOCATOR_H_

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "common/mutex.h"
#include "server/core/hot_region_tuner.h"
#include "server/core/point_locator.h"
#include "server/core/query_histogram.h"
#include "server/core/serving_mesh.h"
#include "server/core/snapshot_slot.h"
#include "server/core/tuning_options.h"
#include "server/core/tuning_state_store.h"

namespace locator {

class SelfTuningLocator : public PointLocator {
 public:
  // `mesh` must outlive the locator. Publishes an initial snapshot tuned for
  // uniform traffic before returning.
  SelfTuningLocator(const ServingMesh& mesh, const TuningOptions& options);
  ~SelfTuningLocator() override;

  void Locate(const Point2& q, LocateResult* result) const override;
  // One snapshot load and one update of the shared counters per call;
  // each walk starts from the previous answer when the previous query is
  // nearer than the table's start.
  void LocateMany(std::span<const Point2> queries, LocateResult* results,
                  Detail detail = Detail::kFull) const override;
  std::string_view name() const override { return "self-tuning"; }
  TuningSummary Summary() const override EXCLUDES(persistence_mu_);
  void Retune() override EXCLUDES(tune_mu_);
  Status SaveState() override EXCLUDES(tune_mu_);

  static constexpr std::chrono::seconds kMinSaveInterval{1};

 private:
  // Publishes the stored state if there is a usable one; true if it did.
  // Records why a stored state was not usable.
  bool RestoreState() EXCLUDES(tune_mu_, persistence_mu_);
  // Saves unless the published snapshot is the one last saved.
  Status SaveLocked() REQUIRES(tune_mu_) EXCLUDES(persistence_mu_);
  // The previous answer of a batch, to chain walks from.
  struct Chain {
    bool valid = false;
    Point2 query;
    uint32_t face = 0;
  };
  // Locates q with `snap` and counts it in the histogram; true if q fell in
  // a cold cell. With `chain`, starts from chain->face when chain->query is
  // nearer q than the table's start, and records q's answer there.
  bool LocateIn(const TuningSnapshot& snap, const Point2& q,
                LocateResult* result, Detail detail = Detail::kFull,
                Chain* chain = nullptr) const;
  // Counts `queries` located (`cold` of them in cold cells) since the last
  // re-tune, and asks for one when due.
  void Account(uint64_t queries, uint64_t cold) const;
  // Asks for a re-tune: runs it inline or wakes the background thread.
  void RequestRetune() const EXCLUDES(tune_mu_);
  // Drains the histogram and publishes a new snapshot.
  void RetuneLocked() const REQUIRES(tune_mu_);
  void TunerLoop() EXCLUDES(tune_mu_);

  const ServingMesh& mesh_;
  const TuningOptions options_;
  mutable QueryHistogram histogram_;

  // Serialises re-tunes. Locate() only ever try-locks it (inline mode), so a
  // query never waits for the tuner.
  mutable Mutex tune_mu_ ACQUIRED_BEFORE(persistence_mu_);
  mutable HotRegionTuner tuner_ GUARDED_BY(tune_mu_);
  mutable std::vector<double> fresh_ GUARDED_BY(tune_mu_);
  mutable std::atomic<uint64_t> retunes_{0};

  // Persistence; null store when nothing persists.
  std::unique_ptr<const TuningStateStore> store_;
  uint64_t saved_version_ GUARDED_BY(tune_mu_) = 1;  // 1: the untuned plan
  std::chrono::steady_clock::time_point last_save_ GUARDED_BY(tune_mu_);
  mutable Mutex persistence_mu_;
  PersistenceSummary persistence_ GUARDED_BY(persistence_mu_);

  mutable SnapshotSlot<TuningSnapshot> snapshot_;  // published by re-tunes
  mutable std::atomic<uint64_t> since_tune_{0};
  mutable std::atomic<uint64_t> cold_hits_{0};
  // Lifetime counts for Summary(): queries in hot and in cold cells.
  mutable std::atomic<uint64_t> hot_queries_{0};
  mutable std::atomic<uint64_t> fallback_queries_{0};

  // Background mode: RequestRetune() bumps requests_, the thread re-tunes.
  mutable std::atomic<uint64_t> requests_{0};
  std::atomic<bool> stopping_{false};
  std::thread tuner_thread_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_SELF_TUNING_LOCATOR_H_
