#include "server/bench/suites/scale_benchmark.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <string_view>

#include "common/random.h"
#include "common/status_macros.h"
#include "common/workload.h"
#include "locator/dataset_sources.h"
#include "server/bench/bench_runner.h"
#include "server/bench/stopwatch.h"
#include "server/bench/suites/cgal_baselines.h"
#include "server/core/cgal/given_mesh.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/strategies/locator_factory.h"
#include "server/core/terrain/fractal_terrain.h"
#include "server/core/terrain/grid/triangulate_grid.h"
#include "server/core/tuning/query_histogram.h"

namespace locator::bench {

namespace {

double NanosSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::nano>(
             std::chrono::steady_clock::now() - start)
      .count();
}

// Counts answers that disagree with the reference answers, and logs the
// first one.
class AnswerChecker {
 public:
  AnswerChecker(const Triangulation& t, std::string label)
      : t_(t), label_(std::move(label)) {}
  void Check(const Point2& q, const LocateResult& got,
             const LocateResult& reference) {
    if (t_.Agrees(q, got, reference)) return;
    if (mismatches_++ == 0) {
      std::fprintf(stderr,
                   "locator-bench: %s disagrees with CGAL at (%.17g, %.17g)\n",
                   label_.c_str(), q.x, q.y);
    }
  }
  size_t mismatches() const { return mismatches_; }

 private:
  const Triangulation& t_;
  std::string label_;
  size_t mismatches_ = 0;
};

// Blobs of the non-uniform dataset (GenerateClusters).
constexpr size_t kClusterBlobs = 20;
// Near-point queries move up to this share of the box's side from a point.
constexpr double kNearPoint = 1e-3;

// `count` queries at points of `dataset` drawn uniformly, each moved by up
// to kNearPoint of the box's side along each axis.
std::vector<Point2> NearPointQueries(const Dataset& dataset,
                                     const BoundingBox& box, size_t count,
                                     uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Point2> queries(count);
  const double dx = kNearPoint * box.width(), dy = kNearPoint * box.height();
  for (Point2& q : queries) {
    const Point2 p = dataset.points[UniformIndex(rng, dataset.points.size())];
    q.x = std::clamp(p.x + UniformDouble(rng, -dx, dx), box.min_x, box.max_x);
    q.y = std::clamp(p.y + UniformDouble(rng, -dy, dy), box.min_y, box.max_y);
  }
  return queries;
}

// Sparse queries: the dataset's box cut into kSparseGrid x kSparseGrid
// cells, and a cell is sparse when it holds at most a tenth of the mean
// number of points per cell.
constexpr int kSparseGrid = 64;

// `count` queries drawn uniformly over the sparse cells of `dataset`'s box:
// the parts of non-uniform data where a hierarchy's coarse levels answer
// from cache. Empty when no cell is sparse.
std::vector<Point2> SparseQueries(const Dataset& dataset,
                                  const BoundingBox& box, size_t count,
                                  uint64_t seed) {
  const GridGeometry grid(box, kSparseGrid);
  std::vector<size_t> points(grid.cells(), 0);
  for (const Point2& p : dataset.points) ++points[grid.CellOf(p)];
  const double limit =
      0.1 * static_cast<double>(dataset.points.size()) / grid.cells();
  std::vector<size_t> sparse;
  for (size_t c = 0; c < points.size(); ++c) {
    if (static_cast<double>(points[c]) <= limit) sparse.push_back(c);
  }
  std::vector<Point2> queries;
  if (sparse.empty()) return queries;
  std::mt19937_64 rng(seed);
  queries.reserve(count);
  while (queries.size() < count) {
    const size_t c = sparse[UniformIndex(rng, sparse.size())];
    const BoundingBox cell = grid.CellBox(static_cast<int>(c % kSparseGrid),
                                          static_cast<int>(c / kSparseGrid));
    queries.push_back(Point2{UniformDouble(rng, cell.min_x, cell.max_x),
                             UniformDouble(rng, cell.min_y, cell.max_y)});
  }
  return queries;
}

// The floor under a locate whose data is not in cache: per query,
// kFloorReads reads of random words of a buffer as large as the serving
// mesh, each address depending on the word read before (as a walk's next
// face depends on the last), timed and sampled as locates are. A uniform
// locate at n = 10^6 reads about as many lines that miss every cache.
// Printed as the strategy "random-reads" beside the uniform workload.
constexpr int kFloorReads = 4;

BenchRow RandomReadsRow(const std::string& workload, size_t n, size_t bytes,
                        std::span<const Point2> queries, int repeats) {
  std::vector<uint64_t> words(std::max<size_t>(1, bytes / sizeof(uint64_t)));
  std::iota(words.begin(), words.end(), uint64_t{0});
  uint64_t chain = 0;
  const auto read = [&](const Point2& q) {
    uint64_t h = std::bit_cast<uint64_t>(q.x);
    for (int i = 0; i < kFloorReads; ++i) {
      h = (h ^ chain) * 0x9E3779B97F4A7C15ull;
      chain += words[((h >> 32) * words.size()) >> 32];
    }
  };
  BenchRow row{"scale", workload, n, "random-reads",
               0,       0,        0, MedianNsPerQuery(queries, repeats, read),
               0};
  const LatencySample latency = SampleLatency(queries, read);
  row.p50_ns = latency.p50_ns;
  row.p999_ns = latency.p999_ns;
  // A volatile store keeps the reads from being optimised away.
  volatile uint64_t keep = chain;
  (void)keep;
  return row;
}

bool Selected(const std::vector<std::string>& names, std::string_view name) {
  return names.empty() ||
         std::find(names.begin(), names.end(), name) != names.end();
}

// The datasets of --scale: uniform points, clustered points, and the TIN
// of a fractal DEM (a mesh given as triangles, as a simplified DEM is
// served).
enum class ScaleData { kUniform, kClusters, kDem };

// The TIN of a fractal DEM of about 4n samples with n vertices (greedy
// insertion with a budget of n), as TriangulateGrid serves it.
Status DemDataset(size_t n, Dataset* out) {
  const auto side = static_cast<uint32_t>(std::ceil(std::sqrt(4.0 * n)));
  const ElevationGrid grid =
      FractalTerrain(side, side, FractalTerrainOptions(), 2);
  TinOptions options;
  options.max_points = n;
  SimplificationStats stats;
  return TriangulateGrid(grid, options, out, &stats);
}

// The --scale workloads on one of the datasets.
std::vector<std::string> WorkloadNames(ScaleData data) {
  if (data == ScaleData::kClusters) {
    return {"clusters-data", "clusters-raster", "clusters-sparse"};
  }
  if (data == ScaleData::kDem) return {"dem-uniform", "dem-raster"};
  std::vector<std::string> names;
  for (WorkloadKind kind : AllWorkloadKinds()) {
    names.emplace_back(WorkloadName(kind));
  }
  names.emplace_back("raster");
  return names;
}

// InvalidArgument naming the first of `names` that is not in `known`.
Status CheckNames(const std::vector<std::string>& names,
                  const std::vector<std::string>& known, const char* what) {
  for (const std::string& name : names) {
    if (!Selected(known, name)) {
      return Status::InvalidArgument(std::string("unknown ") + what + " '" +
                                     name + "'");
    }
  }
  return Status::OK();
}

// Times every strategy over `mesh` (the serving mesh of t's dataset) and
// CGAL's methods on `all` (its first o.warmup queries warm the strategies
// up), adds their rows, and counts answers that disagree with CGAL into
// *mismatches. With `record_build`, also the self-tuning strategy's build
// row and the random-reads floor (RandomReadsRow). On a mesh given as triangles
// (`delaunay` false) CGAL's hierarchy triangulates the points anew, which is
// another triangulation: the reference is then CGAL's locate on t, and there is
// no hierarchy row.
Status RunWorkload(const ScaleOptions& o, const Triangulation& t,
                   const ServingMesh& mesh, CgalBaselines& cgal,
                   const std::string& workload, std::span<const Point2> all,
                   bool record_build, bool delaunay, BenchReport* report,
                   size_t* mismatches) {
  const size_t n = t.input_points();
  const std::span<const Point2> warm = all.first(o.warmup);
  const std::span<const Point2> measured = all.subspan(o.warmup);
  std::vector<LocateResult> reference(measured.size());
  for (size_t i = 0; i < measured.size(); ++i) {
    reference[i] = delaunay ? cgal.LocateHierarchy(measured[i])
                            : t.ReferenceLocate(measured[i]);
  }
  LocateResult r;
  std::vector<LocateResult> batch(measured.size());
  for (const std::string& strategy : StrategyNames()) {
    if (!Selected(o.strategies, strategy)) continue;
    auto start = std::chrono::steady_clock::now();
    ASSIGN_OR_RETURN(std::unique_ptr<PointLocator> locator,
                     MakePointLocator(strategy, mesh, o.tuning));
    const double build_ns = NanosSince(start);
    LocateAll(*locator, warm, nullptr);
    const std::span<const Point2> timed = measured.first(
        strategy == "walk" ? std::min(o.slow_queries, measured.size())
                           : measured.size());
    const TuningSummary before = locator->Summary();
    const Stopwatch watch;
    CostSums sums;
    AnswerChecker checker(t, strategy + " on " + workload);
    for (size_t i = 0; i < timed.size(); ++i) {
      locator->Locate(timed[i], &r);
      sums.Add(r.cost);
      checker.Check(timed[i], r, reference[i]);
    }
    *mismatches += checker.mismatches();
    const auto locate = [&](const Point2& q) {
      locator->Locate(q, &r, Detail::kLocation);
    };
    BenchRow row{"scale",
                 workload,
                 n,
                 strategy,
                 sums.mean_cost(),
                 sums.mean_faces(),
                 sums.mean_comparisons(),
                 MedianNsPerQuery(timed, o.repeats, locate),
                 0};
    const LatencySample latency = SampleLatency(timed, locate);
    row.batch_ns_per_query = MedianNsPerPoint(timed.size(), o.repeats, [&] {
      locator->LocateMany(timed, batch.data(), Detail::kLocation);
    });
    row.full_ns_per_query = MedianNsPerQuery(
        timed, o.repeats, [&](const Point2& q) { locator->Locate(q, &r); });
    const double seconds = watch.Seconds();
    const TuningSummary after = locator->Summary();
    const double located = static_cast<double>(timed.size()) *
                           (3 * static_cast<double>(o.repeats) + 2);
    row.retunes_per_million =
        1e6 * static_cast<double>(after.retune_count - before.retune_count) /
        located;
    row.tune_cpu_share =
        static_cast<double>(after.tune_nanos - before.tune_nanos) /
        (seconds * 1e9);
    row.p50_ns = latency.p50_ns;
    row.p999_ns = latency.p999_ns;
    row.extra_bytes = after.memory_bytes;
    report->Add(row);
    if (record_build && strategy == "self-tuning") {
      report->Add(BenchRow{"build", "-", n, strategy, 0, 0, 0, build_ns,
                           row.extra_bytes});
    }
  }

  AnswerChecker checker(t, "cgal-lasthint on " + workload);
  for (size_t i = 0; i < measured.size(); ++i) {
    checker.Check(measured[i], cgal.LocateLastHint(measured[i]), reference[i]);
  }
  *mismatches += checker.mismatches();
  const std::span<const Point2> slow =
      measured.first(std::min(o.slow_queries, measured.size()));
  report->Add(BenchRow{
      "scale", workload, n, "cgal-nohint", 0, 0, 0,
      MedianNsPerQuery(slow, o.repeats,
                       [&](const Point2& q) { r = cgal.LocateNoHint(q); }),
      0});
  report->Add(BenchRow{
      "scale", workload, n, "cgal-lasthint", 0, 0, 0,
      MedianNsPerQuery(measured, o.repeats,
                       [&](const Point2& q) { r = cgal.LocateLastHint(q); }),
      0});
  if (!delaunay) return Status::OK();
  const auto hierarchy = [&](const Point2& q) { r = cgal.LocateHierarchy(q); };
  BenchRow row{"scale",
               workload,
               n,
               "cgal-hierarchy",
               0,
               0,
               0,
               MedianNsPerQuery(measured, o.repeats, hierarchy),
               cgal.hierarchy_bytes() > t.MemoryBytes()
                   ? cgal.hierarchy_bytes() - t.MemoryBytes()
                   : 0};
  const LatencySample latency = SampleLatency(measured, hierarchy);
  row.p50_ns = latency.p50_ns;
  row.p999_ns = latency.p999_ns;
  report->Add(row);
  if (record_build) {
    report->Add(
        RandomReadsRow(workload, n, mesh.MemoryBytes(), measured, o.repeats));
  }
  return Status::OK();
}

}  // namespace

Status RunScale(const ScaleOptions& o, BenchReport* report) {
  constexpr ScaleData kAll[] = {ScaleData::kUniform, ScaleData::kClusters,
                                ScaleData::kDem};
  std::vector<std::string> known;
  for (const ScaleData data : kAll) {
    for (std::string& name : WorkloadNames(data)) known.push_back(name);
  }
  RETURN_IF_ERROR(CheckNames(o.workloads, known, "workload"));
  RETURN_IF_ERROR(CheckNames(o.strategies, StrategyNames(), "strategy"));
  size_t mismatches = 0;
  const size_t count = o.warmup + o.queries;
  for (size_t n : o.sizes) {
    for (const ScaleData data : kAll) {
      const std::vector<std::string> names = WorkloadNames(data);
      if (std::none_of(names.begin(), names.end(), [&](const std::string& w) {
            return Selected(o.workloads, w);
          })) {
        continue;
      }
      Dataset dataset;
      Status s;
      if (data == ScaleData::kDem) {
        s = DemDataset(n, &dataset);
      } else {
        dataset = data == ScaleData::kClusters
                      ? GenerateClusters(n, kClusterBlobs, 1)
                      : GenerateUniform(n, 1);
      }
      if (!s.ok()) return s;
      const std::string suffix = data == ScaleData::kClusters ? "-clusters"
                                 : data == ScaleData::kDem    ? "-dem"
                                                              : "";
      auto start = std::chrono::steady_clock::now();
      // A mesh given as triangles is served as the engine serves it
      // (BuildGivenMesh); CGAL's triangulation of it is the reference.
      BuiltMesh given;
      if (data == ScaleData::kDem) {
        ASSIGN_OR_RETURN(given, BuildGivenMesh(dataset));
        report->Add(BenchRow{"build", "-", n, "given-mesh" + suffix, 0, 0, 0,
                             NanosSince(start), given.mesh->MemoryBytes()});
        start = std::chrono::steady_clock::now();
      }
      ASSIGN_OR_RETURN(std::unique_ptr<Triangulation> t,
                       Triangulation::Build(dataset));
      // The serving mesh is what answers; CGAL's triangulation builds it.
      report->Add(BenchRow{"build", "-", n, "triangulation" + suffix, 0, 0, 0,
                           NanosSince(start), t->mesh().MemoryBytes()});
      report->Add(BenchRow{"build", "-", n, "cgal-builder" + suffix, 0, 0, 0, 0,
                           t->MemoryBytes()});
      CgalBaselines cgal(*t, dataset);
      if (data != ScaleData::kDem) {
        report->Add(BenchRow{"build", "-", n, "cgal-hierarchy" + suffix, 0, 0,
                             0, cgal.hierarchy_build_seconds() * 1e9,
                             cgal.hierarchy_bytes()});
      }
      const ServingMesh& served =
          data == ScaleData::kDem ? *given.mesh : t->mesh();
      const BoundingBox& box = t->bounding_box();
      std::vector<std::pair<std::string, std::vector<Point2>>> workloads;
      if (data == ScaleData::kClusters) {
        workloads.emplace_back("clusters-data",
                               NearPointQueries(dataset, box, count, 4243));
        workloads.emplace_back("clusters-raster", RasterQueries(box, count));
        workloads.emplace_back("clusters-sparse",
                               SparseQueries(dataset, box, count, 4245));
      } else if (data == ScaleData::kDem) {
        workloads.emplace_back(
            "dem-uniform",
            WorkloadQueries(WorkloadKind::kUniform, box, count, 4244));
        workloads.emplace_back("dem-raster", RasterQueries(box, count));
      } else {
        for (WorkloadKind kind : AllWorkloadKinds()) {
          workloads.emplace_back(
              std::string(WorkloadName(kind)),
              WorkloadQueries(kind, box, count, 4242 + static_cast<int>(kind)));
        }
        workloads.emplace_back("raster", RasterQueries(box, count));
      }
      for (const auto& [workload, queries] : workloads) {
        if (!Selected(o.workloads, workload)) continue;
        s = RunWorkload(o, *t, served, cgal, workload, queries,
                        workload == "uniform", data != ScaleData::kDem, report,
                        &mismatches);
        if (!s.ok()) return s;
      }
    }
  }
  if (mismatches > 0) {
    return Status::Internal(std::to_string(mismatches) +
                            " answers disagreed with CGAL");
  }
  return Status::OK();
}

}  // namespace locator::bench
