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
// by a mutex only the tuner holds: on a background thread, or inline
// (options.background == false, deterministic). Inline, no query pays for a
// whole re-tune: the query that triggers one drains the histogram and plans
// (O(coarse cells)), and the new table is built kTuneUnitsPerQuery starts
// per located query (StartTable::Builder) by the queries that follow, which
// keep the old snapshot until the new one is published complete.
//
// Sweeps: a scan moving steadily along rows or columns (a raster) keeps
// entering cells the plan thought cold, and chasing its front would re-tune
// all the time. Every kSweepWindow queries the moves between cells are
// judged (QueryHistogram::DrainSteps); while they go one way along an axis,
// no re-tune starts, and the histogram keeps accumulating the swept area:
// when the sweep ends, the next re-tune plans for all of it. Traffic whose
// moves go both ways (a hot spot, moved or not) re-tunes as before.
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
#include "locator/tuning_options.h"
#include "server/core/mesh/scan_lookahead.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/point_locator.h"
#include "server/core/tuning/hot_region_tuner.h"
#include "server/core/tuning/query_histogram.h"
#include "server/core/tuning/snapshot_slot.h"
#include "server/core/tuning/tuning_state_store.h"

namespace locator {

class SelfTuningLocator : public PointLocator {
 public:
  // `mesh` must outlive the locator. Publishes an initial snapshot before
  // returning: the saved state if there is one (options.state_dir), else
  // the table planned for uniform traffic; in background mode a table with
  // one start per coarse cell stands in for that one until the tuner thread
  // has built it, so that construction costs O(cells) walks, not the
  // budget's.
  SelfTuningLocator(const ServingMesh& mesh, const TuningOptions& options);
  ~SelfTuningLocator() override;

  // When the thread's queries advance by a constant step (a raster row, a
  // sampled profile), also prefetches the starts of the next ones.
  void Locate(const Point2& q, LocateResult* result,
              Detail detail = Detail::kFull) const override;
  // One snapshot load and one update of the shared counters per call;
  // each walk starts from the previous answer when the previous query is
  // nearer than the table's start, and the next queries' starts are
  // prefetched while it walks.
  void LocateMany(std::span<const Point2> queries, LocateResult* results,
                  Detail detail = Detail::kFull) const override;
  std::string_view name() const override { return "self-tuning"; }
  TuningSummary Summary() const override EXCLUDES(persistence_mu_);
  void Retune() override EXCLUDES(tune_mu_);
  Status SaveState() override EXCLUDES(tune_mu_);

  static constexpr std::chrono::seconds kMinSaveInterval{1};
  // Inline mode: the most table-building units (StartTable::Builder) a
  // located query does.
  static constexpr size_t kTuneUnitsPerQuery = 8;
  // Queries per sweep judgement.
  static constexpr uint64_t kSweepWindow = 1024;
  // Single locates reach the shared counters in batches of up to this many
  // per histogram shard: a query then costs no atomic read-modify-write
  // beyond its histogram count.
  static constexpr uint64_t kAccountBatch = 64;

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
  // Prefetches what the walks for the next three queries read first, in
  // three stages that each use what the previous call fetched: third's
  // table slot, second's start face, next's start corners.
  void PrefetchStarts(const TuningSnapshot& snap, const Point2& next,
                      const Point2& second, const Point2& third) const;
  // Counts `queries` located (`cold` of them in cold cells) since the last
  // re-tune, and starts one or advances the pending one (inline: by the
  // work of `tune_queries` queries).
  void Account(uint64_t queries, uint64_t cold, uint64_t tune_queries) const
      EXCLUDES(tune_mu_);
  // Whether a shard's `pending` single locates go through Account() now:
  // at kAccountBatch, where Due() may judge (so that one thread's re-tunes
  // come exactly when they would per query), and while an inline build is
  // pending (each query advances it).
  bool AccountNow(uint64_t pending) const;
  // Whether the call that took the re-tune counter from `before` to `now`
  // makes a re-tune due; judges the cold block it completes.
  bool Due(uint64_t before, uint64_t now) const;
  // Inline mode, never waiting: advances the pending build by up to
  // kTuneUnitsPerQuery * queries units, or starts a re-tune if `start` and
  // none is pending; publishes the snapshot once complete.
  void TuneInline(bool start, uint64_t queries) const EXCLUDES(tune_mu_);
  // Drains the histogram into the tuner and plans; the build is pending.
  void StartRetuneLocked() const REQUIRES(tune_mu_);
  // Publishes the tuner's current plan as the next snapshot.
  void PublishLocked() const REQUIRES(tune_mu_);
  // A whole re-tune: starts one, builds it and publishes it.
  void RetuneLocked() const REQUIRES(tune_mu_);
  // Adds the time since `begin` to the tuning time, and `units` done for
  // `queries` located queries (0: none) to the per-query maximum.
  void RecordTuning(std::chrono::steady_clock::time_point begin, size_t units,
                    uint64_t queries) const REQUIRES(tune_mu_);
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
  // Inline mode: a build is pending; queries advance it.
  mutable std::atomic<bool> building_{false};
  mutable std::atomic<uint64_t> tune_nanos_{0};
  mutable std::atomic<uint64_t> max_units_per_query_{0};

  // Persistence; null store when nothing persists.
  std::unique_ptr<const TuningStateStore> store_;
  uint64_t saved_version_ GUARDED_BY(tune_mu_) = 1;  // 1: the untuned plan
  // Background mode: the coarse stand-in is published; the tuner thread's
  // first task is the table planned for uniform traffic (version 1 still).
  mutable bool initial_pending_ GUARDED_BY(tune_mu_) = false;
  std::chrono::steady_clock::time_point last_save_ GUARDED_BY(tune_mu_);
  mutable Mutex persistence_mu_;
  PersistenceSummary persistence_ GUARDED_BY(persistence_mu_);

  mutable SnapshotSlot<TuningSnapshot> snapshot_;  // published by re-tunes
  mutable std::atomic<uint64_t> since_tune_{0};
  mutable std::atomic<uint64_t> cold_hits_{0};
  // The last sweep judgement: traffic moves one way; re-tunes wait.
  mutable std::atomic<bool> sweeping_{false};
  // Lifetime counts: queries located (sweep windows count these, which
  // re-tunes do not reset), and those in cold cells.
  mutable std::atomic<uint64_t> located_{0};
  mutable std::atomic<uint64_t> fallback_queries_{0};
  // Per histogram shard, in one cache line: its single locates not yet
  // accounted (see AccountNow()), and the scan its queries may be making.
  // Relaxed loads and stores, no read-modify-write: threads beyond kShards
  // that share a shard may rarely lose a count, which only delays a
  // re-tune, or spoil a prediction.
  struct alignas(64) ShardState {
    std::atomic<uint32_t> queries{0};
    std::atomic<uint32_t> cold{0};
    ScanLookahead lookahead;
  };
  mutable ShardState shards_[QueryHistogram::kShards];

  // Background mode: Account() bumps requests_, the thread re-tunes.
  mutable std::atomic<uint64_t> requests_{0};
  std::atomic<bool> stopping_{false};
  std::thread tuner_thread_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_SELF_TUNING_LOCATOR_H_
