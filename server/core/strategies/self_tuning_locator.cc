#include "server/core/strategies/self_tuning_locator.h"

#include <algorithm>
#include <cstdint>

#include "server/core/mesh/mesh_walk.h"
#include "server/core/tuning/hot_regions.h"

namespace locator {

namespace {

// Judge blocks of this many queries for moved traffic, once a quarter of the
// regular re-tune interval has given the histogram some evidence.
constexpr uint64_t kColdCheckEvery = 256;
// A re-tune is due early when this share of queries lands in cold cells.
// Mixed traffic (half clustered, half uniform) stays below it.
constexpr double kColdShareTrigger = 0.75;
// Start points reported by Summary().
constexpr size_t kSummaryStartPoints = 2000;
// A window's moves are a sweep when, along one axis, at least this many go
// one way, and kSweepRatio times as many as go back. A row-order raster up
// to 4096 queries wide moves 8 cells right per 1024 queries on a 32-cell
// grid, and left once per row; a hot spot moves both ways alike.
constexpr uint64_t kMinSweepSteps = 8;
constexpr uint64_t kSweepRatio = 4;

bool OneWay(uint64_t forth, uint64_t back) {
  const uint64_t more = std::max(forth, back);
  return more >= kMinSweepSteps && more >= kSweepRatio * std::min(forth, back);
}

bool IsSweep(const CellSteps& steps) {
  return OneWay(steps.right, steps.left) || OneWay(steps.up, steps.down);
}

}  // namespace

SelfTuningLocator::SelfTuningLocator(const ServingMesh& mesh,
                                     const TuningOptions& options)
    : mesh_(mesh),
      options_(options),
      histogram_(GridGeometry(
          mesh.bounding_box(),
          HotRegionTuner::CoarseGridSize(HotRegionTuner::Budget(mesh, options),
                                         options.grid_size))),
      tuner_(mesh, histogram_.grid(), options, histogram_.MemoryBytes()) {
  if (!options_.state_dir.empty()) {
    store_ = std::make_unique<const TuningStateStore>(
        options_.state_dir, tuner_.Fingerprint(name()));
    persistence_.state_path = store_->path();
  }
  const bool restored = RestoreState();
  const bool defer_initial = !restored && options_.background;
  if (defer_initial) {
    initial_pending_ = true;
    snapshot_.Publish(tuner_.CoarseSnapshot(1));
  } else if (!restored) {
    snapshot_.Publish(tuner_.Build(1));
  }
  if (options_.background) {
    tuner_thread_ = std::thread([this] { TunerLoop(); });
    if (defer_initial) {
      requests_.fetch_add(1, std::memory_order_release);
      requests_.notify_one();
    }
  }
}

SelfTuningLocator::~SelfTuningLocator() {
  if (tuner_thread_.joinable()) {
    stopping_.store(true);
    requests_.fetch_add(1);
    requests_.notify_one();
    tuner_thread_.join();
  }
}

bool SelfTuningLocator::LocateIn(const TuningSnapshot& snap, const Point2& q,
                                 LocateResult* result, Detail detail,
                                 Chain* chain) const {
  uint32_t lookups = 0;
  uint32_t start = snap.table->Start(q, &lookups);
  // The start's record loads while the query is counted.
  mesh_.PrefetchFace(start);
  const size_t cell = histogram_.grid().CellOf(q);
  histogram_.AddToCell(cell);
  result->cost = LocateCost();
  if (chain && chain->valid &&
      SquaredDistance(chain->query, q) <
          SquaredDistance(mesh_.CornerPoint(start, 0), q)) {
    start = chain->face;
  }
  const uint32_t end = WalkAndDescribe(mesh_, start, q, result, detail);
  if (chain) *chain = Chain{true, q, end};
  result->cost.table_lookups = lookups;
  return !snap.hot[cell];
}

void SelfTuningLocator::Account(uint64_t queries, uint64_t cold,
                                uint64_t tune_queries) const {
  const uint64_t located =
      located_.fetch_add(queries, std::memory_order_relaxed);
  if (located / kSweepWindow != (located + queries) / kSweepWindow) {
    sweeping_.store(IsSweep(histogram_.DrainSteps()),
                    std::memory_order_relaxed);
  }
  const uint64_t before =
      since_tune_.fetch_add(queries, std::memory_order_relaxed);
  if (cold > 0) {
    cold_hits_.fetch_add(cold, std::memory_order_relaxed);
    fallback_queries_.fetch_add(cold, std::memory_order_relaxed);
  }
  const bool due = Due(before, before + queries);
  if (options_.background) {
    if (due) {
      requests_.fetch_add(1, std::memory_order_release);
      requests_.notify_one();
    }
    return;
  }
  if (due || building_.load(std::memory_order_relaxed)) {
    TuneInline(due, tune_queries);
  }
}

bool SelfTuningLocator::AccountNow(uint64_t pending) const {
  if (pending >= kAccountBatch || building_.load(std::memory_order_relaxed)) {
    return true;
  }
  const uint64_t total = since_tune_.load(std::memory_order_relaxed) + pending;
  return total % kColdCheckEvery == 0 || total == options_.retune_every;
}

bool SelfTuningLocator::Due(uint64_t before, uint64_t now) const {
  const bool sweeping = sweeping_.load(std::memory_order_relaxed);
  const uint64_t every = options_.retune_every;
  if (before < every && now >= every) return !sweeping;
  if (before / kColdCheckEvery == now / kColdCheckEvery) return false;
  // The call that completes a block judges it: most of its queries in cold
  // cells means the traffic moved, and waiting for the regular re-tune
  // would serve it badly for up to `every` queries. Unless a sweep explains
  // them: then its front, not a hot spot, is what moved.
  const uint64_t block_cold = cold_hits_.exchange(0, std::memory_order_relaxed);
  if (sweeping) return false;
  // A regular re-tune that a sweep deferred is due once it ended.
  return now >= every ||
         (now >= every / 4 &&
          block_cold >
              kColdShareTrigger * static_cast<double>(kColdCheckEvery));
}

void SelfTuningLocator::PrefetchStarts(const TuningSnapshot& snap,
                                       const Point2& next, const Point2& second,
                                       const Point2& third) const {
  // Each stage reads only what the previous query's call fetched.
  const StartTable& table = *snap.table;
  uint32_t lookups = 0;
  Prefetch(table.Slot(third, &lookups));
  mesh_.PrefetchFace(table.Start(second, &lookups));
  mesh_.PrefetchCorners(table.Start(next, &lookups));
}

void SelfTuningLocator::Locate(const Point2& q, LocateResult* result,
                               Detail detail) const {
  const TuningSnapshot& snap = *snapshot_.Get();
  ShardState& pending = shards_[QueryHistogram::ThreadShard()];
  Point2 step;
  if (pending.lookahead.Observe(q, &step)) {
    PrefetchStarts(snap, Point2{q.x + step.x, q.y + step.y},
                   Point2{q.x + 2 * step.x, q.y + 2 * step.y},
                   Point2{q.x + 3 * step.x, q.y + 3 * step.y});
  }
  const bool cold = LocateIn(snap, q, result, detail);
  const uint32_t queries = pending.queries.load(std::memory_order_relaxed) + 1;
  const uint32_t cold_queries =
      pending.cold.load(std::memory_order_relaxed) + (cold ? 1 : 0);
  if (!AccountNow(queries)) {
    pending.queries.store(queries, std::memory_order_relaxed);
    pending.cold.store(cold_queries, std::memory_order_relaxed);
    return;
  }
  pending.queries.store(0, std::memory_order_relaxed);
  pending.cold.store(0, std::memory_order_relaxed);
  Account(queries, cold_queries, /*tune_queries=*/1);
}

void SelfTuningLocator::LocateMany(std::span<const Point2> queries,
                                   LocateResult* results, Detail detail) const {
  const TuningSnapshot& snap = *snapshot_.Get();
  uint64_t cold = 0;
  Chain chain;
  for (size_t i = 0; i < queries.size(); ++i) {
    if (i + 3 < queries.size()) {
      PrefetchStarts(snap, queries[i + 1], queries[i + 2], queries[i + 3]);
    }
    cold += LocateIn(snap, queries[i], &results[i], detail, &chain);
  }
  Account(queries.size(), cold, queries.size());
}

void SelfTuningLocator::TuneInline(bool start, uint64_t queries) const {
  // Whoever finds the tuner busy just keeps using the old snapshot.
  if (!tune_mu_.TryLock()) return;
  const auto begin = std::chrono::steady_clock::now();
  const bool pending = tuner_.building();
  if (pending || start) {
    if (!pending) StartRetuneLocked();
    size_t units = 0;
    if (tuner_.BuildStep(kTuneUnitsPerQuery * queries, &units)) {
      PublishLocked();
    }
    building_.store(tuner_.building(), std::memory_order_relaxed);
    RecordTuning(begin, units, queries);
  }
  tune_mu_.Unlock();
}

void SelfTuningLocator::TunerLoop() {
  uint64_t seen = 0;
  for (;;) {
    requests_.wait(seen, std::memory_order_acquire);
    seen = requests_.load(std::memory_order_acquire);
    if (stopping_.load()) return;
    MutexLock lock(&tune_mu_);
    if (initial_pending_) {
      // Not a re-tune: the table the constructor would have built inline.
      snapshot_.Publish(tuner_.Build(1));
      initial_pending_ = false;
      // A re-tune that came due meanwhile was folded into this request.
      if (since_tune_.load(std::memory_order_relaxed) < options_.retune_every) {
        continue;
      }
    }
    RetuneLocked();
    if (store_ &&
        std::chrono::steady_clock::now() - last_save_ >= kMinSaveInterval) {
      // Ignored: a failure is recorded in the summary (Stats() shows it),
      // and the next re-tune tries again.
      (void)SaveLocked();
    }
  }
}

bool SelfTuningLocator::RestoreState() {
  if (!store_) return false;
  TuningState state;
  std::shared_ptr<const TuningSnapshot> snapshot;
  // Uncontended: the constructor calls this before the tuner thread exists.
  MutexLock tune_lock(&tune_mu_);
  Status status = store_->Load(&state);
  if (status.ok()) {
    status = tuner_.Restore(state, state.snapshot_version, &snapshot);
  }
  MutexLock lock(&persistence_mu_);
  if (!status.ok()) {
    // No file yet is the normal first start, not a problem to report.
    if (status.code() != Status::Code::kNotFound) {
      persistence_.load_error = status.message();
    }
    return false;
  }
  snapshot_.Publish(std::move(snapshot));
  retunes_.store(state.retune_count, std::memory_order_relaxed);
  saved_version_ = state.snapshot_version;
  persistence_.restored_from_state = true;
  return true;
}

Status SelfTuningLocator::SaveState() {
  MutexLock lock(&tune_mu_);
  return SaveLocked();
}

Status SelfTuningLocator::SaveLocked() {
  const std::shared_ptr<const TuningSnapshot> snapshot = snapshot_.Current();
  if (!store_ || snapshot->version == saved_version_) return Status::OK();
  TuningState state;
  tuner_.ExportState(&state);
  state.snapshot_version = snapshot->version;
  state.retune_count = retunes_.load(std::memory_order_relaxed);
  const Status status = store_->Save(state);
  last_save_ = std::chrono::steady_clock::now();
  if (status.ok()) saved_version_ = snapshot->version;
  MutexLock lock(&persistence_mu_);
  persistence_.saves += status.ok() ? 1 : 0;
  persistence_.save_error = status.ok() ? "" : status.message();
  return status;
}

void SelfTuningLocator::Retune() {
  MutexLock lock(&tune_mu_);
  RetuneLocked();
}

void SelfTuningLocator::StartRetuneLocked() const {
  std::fill(fresh_.begin(), fresh_.end(), 0.0);
  histogram_.Drain(&fresh_);
  tuner_.AddCounts(fresh_);
  tuner_.Plan();
  since_tune_.store(0, std::memory_order_relaxed);
  cold_hits_.store(0, std::memory_order_relaxed);
}

void SelfTuningLocator::PublishLocked() const {
  snapshot_.Publish(tuner_.Snapshot(snapshot_.Current()->version + 1));
  retunes_.fetch_add(1, std::memory_order_relaxed);
}

void SelfTuningLocator::RetuneLocked() const {
  initial_pending_ = false;  // the re-tune builds a full table
  const auto begin = std::chrono::steady_clock::now();
  StartRetuneLocked();
  size_t units = 0;
  tuner_.BuildStep(SIZE_MAX, &units);
  PublishLocked();
  building_.store(false, std::memory_order_relaxed);
  RecordTuning(begin, units, 0);
}

void SelfTuningLocator::RecordTuning(
    std::chrono::steady_clock::time_point begin, size_t units,
    uint64_t queries) const {
  tune_nanos_.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(
                            std::chrono::steady_clock::now() - begin)
                            .count(),
                        std::memory_order_relaxed);
  if (queries == 0) return;
  const uint64_t per_query = (units + queries - 1) / queries;
  if (per_query > max_units_per_query_.load(std::memory_order_relaxed)) {
    max_units_per_query_.store(per_query, std::memory_order_relaxed);
  }
}

TuningSummary SelfTuningLocator::Summary() const {
  const std::shared_ptr<const TuningSnapshot> snap = snapshot_.Current();
  TuningSummary s;
  s.snapshot_version = snap->version;
  s.retune_count = retunes_.load(std::memory_order_relaxed);
  s.grid_size = histogram_.grid().size();
  s.grid_box = histogram_.grid().box();
  s.histogram = snap->histogram;
  s.hot_regions = FindHotRegions(histogram_.grid(), snap->histogram);
  s.start_points = snap->table->SampleStartPoints(kSummaryStartPoints);
  s.start_point_count = snap->table->start_count();
  s.memory_bytes = snap->memory_bytes + histogram_.MemoryBytes();
  MutexLock lock(&persistence_mu_);
  s.persistence = persistence_;
  // Fallbacks first: each is in located_ before it is in fallback_queries_.
  uint64_t fallback = fallback_queries_.load(std::memory_order_relaxed);
  uint64_t located = located_.load(std::memory_order_relaxed);
  for (const ShardState& pending : shards_) {
    fallback += pending.cold.load(std::memory_order_relaxed);
    located += pending.queries.load(std::memory_order_relaxed);
  }
  s.fallback_queries = fallback;
  s.hot_queries = located >= fallback ? located - fallback : 0;
  s.tune_nanos = tune_nanos_.load(std::memory_order_relaxed);
  s.max_tune_units_per_query =
      max_units_per_query_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace locator
