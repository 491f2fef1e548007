#include "locator/engine.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <utility>

#include "common/hilbert.h"
#include "common/input_text.h"
#include "common/status_macros.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/locator_factory.h"
#include "server/core/strategies/point_locator.h"
#include "server/core/walk_cost_histogram.h"

namespace locator {

namespace {

// Points located between two polls of the batch's keep_going callback:
// small enough to notice a cancellation within ~0.1 ms, large enough that
// polling is free.
constexpr size_t kBatchChunk = 256;

Status CheckFinite(const Point2& q, const std::string& what) {
  if (IsFinite(q)) return Status::OK();
  // In shortest form: std::to_string would print the finite one of
  // (NaN, 1.8e308) as 309 digits.
  return Status::InvalidArgument(what + " has a non-finite coordinate " +
                                 PointText(q));
}

}  // namespace

Status CheckBatchPoint(const Point2& q, size_t index) {
  if (IsFinite(q)) return Status::OK();
  return CheckFinite(q, "point " + std::to_string(index));
}

Engine::Engine() : walk_costs_(std::make_unique<WalkCostHistogram>()) {}
Engine::~Engine() = default;

StatusOr<std::unique_ptr<Engine>> Engine::Create(Dataset dataset,
                                                 const EngineOptions& options) {
  return Build(std::move(dataset), std::nullopt, options);
}

StatusOr<std::unique_ptr<Engine>> Engine::CreateSimplified(
    Dataset tin, const SimplificationStats& simplification,
    const EngineOptions& options) {
  return Build(std::move(tin), simplification, options);
}

StatusOr<std::unique_ptr<Engine>> Engine::Build(
    Dataset dataset, std::optional<SimplificationStats> simplification,
    const EngineOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<Engine> e(new Engine());
  BuiltMesh built;
  const unsigned threads =
      options.build_threads > 0
          ? options.build_threads
          : std::max(1u, std::thread::hardware_concurrency());
  RETURN_IF_ERROR(BuildOrMapMesh(dataset, options.mesh_cache_dir, &built,
                                 &e->info_.mesh_cache, threads));
  e->info_.source = std::move(dataset.source);
  e->info_.crs = std::move(dataset.crs);
  e->info_.simplification = simplification;
  return Finish(std::move(built), options, start, std::move(e));
}

StatusOr<std::unique_ptr<Engine>> Engine::CreateFromMeshFile(
    uint64_t fingerprint, DatasetOrigin origin, const EngineOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<Engine> e(new Engine());
  BuiltMesh built;
  RETURN_IF_ERROR(MapCachedMesh(options.mesh_cache_dir, fingerprint, &built,
                                &e->info_.mesh_cache));
  e->info_.source = std::move(origin.source);
  e->info_.crs = std::move(origin.crs);
  e->info_.simplification = std::move(origin.simplification);
  return Finish(std::move(built), options, start, std::move(e));
}

StatusOr<std::unique_ptr<Engine>> Engine::Finish(
    BuiltMesh built, const EngineOptions& options,
    std::chrono::steady_clock::time_point start, std::unique_ptr<Engine> e) {
  e->mesh_ = std::move(built.mesh);
  e->edge_sample_ = std::move(built.facts.edge_sample);
  e->outline_ = std::move(built.facts.outline);
  ASSIGN_OR_RETURN(e->locator_, MakePointLocator(options.strategy, *e->mesh_,
                                                 options.tuning));
  const ServingMesh& mesh = *e->mesh_;
  DatasetInfo& info = e->info_;
  info.input_points = mesh.input_points();
  info.vertices = mesh.num_vertices();
  info.duplicates_merged = built.facts.duplicates_merged;
  info.triangles = mesh.num_triangles();
  info.all_triangles = mesh.num_faces();
  info.constraints = built.facts.constraints;
  info.holes = built.facts.holes;
  info.bounding_box = mesh.bounding_box();
  info.has_values = mesh.has_values();
  info.triangulation_bytes = mesh.MemoryBytes();
  info.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return e;
}

void Engine::Record(uint64_t queries, uint64_t cost) const {
  queries_.fetch_add(queries, std::memory_order_relaxed);
  cost_sum_.fetch_add(cost, std::memory_order_relaxed);
  window_cost_.fetch_add(cost, std::memory_order_relaxed);
  // The call that completes a window publishes its mean; costs that race
  // with the reset land in the next window, which is fine for a statistic.
  const uint64_t before =
      window_count_.fetch_add(queries, std::memory_order_relaxed);
  if (before < kStatsWindow && before + queries >= kStatsWindow) {
    const uint64_t sum = window_cost_.exchange(0, std::memory_order_relaxed);
    const uint64_t count = window_count_.exchange(0, std::memory_order_relaxed);
    last_window_mean_.store(static_cast<double>(sum) / count,
                            std::memory_order_relaxed);
  }
}

Status Engine::Locate(const Point2& q, LocateResult* result,
                      Interpolation how) const {
  RETURN_IF_ERROR(CheckFinite(q, "query point"));
  RETURN_IF_ERROR(CheckInterpolation(how));
  const Detail detail = StrategyDetail(how, Detail::kFull);
  locator_->Locate(q, result, detail);
  if (detail == Detail::kAllButValue) {
    InterpolateValues(std::span(&q, 1), how, result);
  }
  Record(1, result->cost.total());
  walk_costs_->Add(result->cost.faces_visited);
  return Status::OK();
}

Status Engine::LocateBatch(std::span<const Point2> queries,
                           std::vector<LocateResult>* results,
                           const std::function<bool()>& keep_going,
                           Interpolation how, Detail detail) const {
  for (size_t i = 0; i < queries.size(); ++i) {
    RETURN_IF_ERROR(CheckBatchPoint(queries[i], i));
  }
  RETURN_IF_ERROR(CheckInterpolation(how));
  results->resize(queries.size());
  const std::vector<uint32_t> order = HilbertOrder(queries, info_.bounding_box);
  const Detail strategy_detail = StrategyDetail(how, detail);
  Point2 sorted[kBatchChunk];
  std::vector<LocateResult> located(kBatchChunk);
  for (size_t begin = 0; begin < queries.size(); begin += kBatchChunk) {
    if (keep_going && !keep_going()) return Status::Unavailable("cancelled");
    const size_t count = std::min(queries.size() - begin, kBatchChunk);
    for (size_t i = 0; i < count; ++i) sorted[i] = queries[order[begin + i]];
    const std::span<const Point2> chunk(sorted, count);
    locator_->LocateMany(chunk, located.data(), strategy_detail);
    if (strategy_detail == Detail::kAllButValue) {
      InterpolateValues(chunk, how, located.data());
    }
    uint64_t cost = 0;
    for (size_t i = 0; i < count; ++i) cost += located[i].cost.total();
    Record(count, cost);
    walk_costs_->AddAll(std::span(located).first(count));
    for (size_t i = 0; i < count; ++i) {
      (*results)[order[begin + i]] = located[i];
    }
  }
  return Status::OK();
}

void Engine::Retune() { locator_->Retune(); }

Status Engine::SaveTuningState() { return locator_->SaveState(); }

EngineStats Engine::Stats() const {
  EngineStats s;
  s.dataset = info_;
  s.strategy = std::string(locator_->name());
  s.queries = queries_.load(std::memory_order_relaxed);
  s.total_cost = cost_sum_.load(std::memory_order_relaxed);
  s.mean_cost_lifetime =
      s.queries ? static_cast<double>(s.total_cost) / s.queries : 0;
  const double recent = last_window_mean_.load(std::memory_order_relaxed);
  s.mean_cost_recent = recent >= 0 ? recent : s.mean_cost_lifetime;
  s.walk_costs = walk_costs_->Counts();
  s.tuning = locator_->Summary();
  return s;
}

}  // namespace locator
