#include "server/bench/suites/paper_benchmark.h"

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "common/status_macros.h"
#include "common/workload.h"
#include "locator/dataset_sources.h"
#include "server/bench/bench_runner.h"
#include "server/bench/paper_figures.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/strategies/locator_factory.h"

namespace locator::bench {

namespace {

using Key = std::pair<std::string, std::string>;  // (workload, strategy)

// How many disagreements the message of RunPaper's error lists.
constexpr size_t kDisagreementsShown = 5;

struct SizeResults {
  std::map<Key, CostSums> sums;
  std::map<Key, double> bytes;
  // drift windows per strategy, by window start (query index)
  std::map<std::string, std::map<size_t, CostSums>> drift;
};

// Answers that disagree with CGAL's own locate(), counted and described.
struct Disagreements {
  size_t count = 0;
  std::string first;  // the first kDisagreementsShown, one per line

  void Add(const std::string& strategy, const Point2& q,
           const LocateResult& got, const LocateResult& reference) {
    if (count++ >= kDisagreementsShown) return;
    char line[256];
    std::snprintf(line, sizeof line,
                  "\n  %s at (%.17g, %.17g): %s triangle %lld, CGAL %s "
                  "triangle %lld",
                  strategy.c_str(), q.x, q.y,
                  std::string(LocationTypeName(got.type)).c_str(),
                  static_cast<long long>(got.triangle_id),
                  std::string(LocationTypeName(reference.type)).c_str(),
                  static_cast<long long>(reference.triangle_id));
    first += line;
  }
};

// One query stream of one workload, with CGAL's answers when verifying.
struct Stream {
  WorkloadKind kind;
  std::vector<Point2> queries;
  std::vector<LocateResult> references;  // empty unless verifying
};

// Locates queries [begin, end) of `stream` in order, adding their costs to
// *sums (if given) and checking them against the references (if any).
void LocateRange(const PointLocator& locator, const Triangulation& t,
                 const std::string& strategy, const Stream& stream,
                 size_t begin, size_t end, CostSums* sums,
                 Disagreements* disagreements) {
  LocateResult r;
  for (size_t i = begin; i < end; ++i) {
    const Point2& q = stream.queries[i];
    locator.Locate(q, &r);
    if (sums) sums->Add(r.cost);
    if (!stream.references.empty() && !t.Agrees(q, r, stream.references[i])) {
      disagreements->Add(strategy, q, r, stream.references[i]);
    }
  }
}

// Runs one strategy over one query stream: warm-up, then measurement (in
// windows for drift).
Status RunStream(const PaperOptions& o, const Triangulation& t,
                 const std::string& strategy, const Stream& stream,
                 SizeResults* out, Disagreements* disagreements) {
  ASSIGN_OR_RETURN(std::unique_ptr<PointLocator> locator,
                   MakePointLocator(strategy, t.mesh(), o.tuning));
  const size_t total = stream.queries.size();
  LocateRange(*locator, t, strategy, stream, 0, o.warmup, nullptr,
              disagreements);
  const Key key(std::string(WorkloadName(stream.kind)), strategy);
  if (stream.kind != WorkloadKind::kDrift) {
    LocateRange(*locator, t, strategy, stream, o.warmup, total, &out->sums[key],
                disagreements);
  } else {
    for (size_t begin = o.warmup; begin < total; begin += o.drift_window) {
      CostSums window;
      LocateRange(*locator, t, strategy, stream, begin,
                  std::min(begin + o.drift_window, total), &window,
                  disagreements);
      out->drift[strategy][begin].Add(window);
      out->sums[key].Add(window);
    }
  }
  out->bytes[key] += locator->Summary().memory_bytes;
  return Status::OK();
}

// The paper's four workloads plus uniform; all of them (with mixed and drift)
// for the paper's own setting.
std::vector<WorkloadKind> Workloads(const PaperOptions& o) {
  if (!o.domain) return AllWorkloadKinds();
  return {WorkloadKind::kUniform, WorkloadKind::kOneCluster,
          WorkloadKind::kThreeCluster, WorkloadKind::kDCluster,
          WorkloadKind::kXCluster};
}

// Refuses to measure a triangulation that does not serve the dataset's
// constraints (an engine that triangulates the points alone would give
// Delaunay figures under a non-Delaunay name). Necessary conditions: the
// breakline and ring corners (distinct from the points in these datasets)
// are vertices too; the triangles, when given, are faces and as many as the
// triangulation's in-domain triangles.
Status CheckServesConstraints(const Dataset& dataset, const Triangulation& t) {
  const DatasetConstraints& c = dataset.constraints;
  size_t corners = 0;
  for (const auto* lines : {&c.breaklines, &c.rings}) {
    for (const Polyline& line : *lines) corners += line.points.size();
  }
  if (t.num_vertices() < dataset.points.size() + corners) {
    return Status::FailedPrecondition(
        dataset.source + ": " + std::to_string(dataset.points.size()) +
        " points and " + std::to_string(corners) + " constraint corners, " +
        std::to_string(t.num_vertices()) +
        " vertices: the engine does not build constrained triangulations");
  }
  if (!c.triangles.empty() && c.triangles.size() != t.num_triangles()) {
    return Status::FailedPrecondition(
        dataset.source + ": " + std::to_string(c.triangles.size()) +
        " triangles given, " + std::to_string(t.num_triangles()) +
        " served: the engine does not serve meshes as given");
  }
  for (size_t i = 0; i < c.triangles.size(); ++i) {
    Triangulation::Face_handle face;
    if (!t.FaceWithCorners(c.triangles[i], &face)) {
      return Status::FailedPrecondition(
          dataset.source + ": given triangle " + std::to_string(i) +
          " is not a face of the triangulation: the engine does not serve "
          "meshes as given");
    }
  }
  return Status::OK();
}

Dataset MakeDataset(const PaperOptions& o, size_t n, int seed) {
  if (!o.domain) return GenerateUniform(n, seed);
  return GenerateDomainDataset(*o.domain, n, seed).dataset;
}

}  // namespace

Status RunPaper(const PaperOptions& o, BenchReport* report) {
  std::vector<size_t> sizes = o.sizes;
  if (sizes.empty()) sizes.assign(kPaperSizes.begin(), kPaperSizes.end());
  const std::string mode =
      o.domain ? "paper-" + std::string(DomainKindName(*o.domain)) : "paper";
  const std::vector<WorkloadKind> workloads = Workloads(o);
  // The points' square, and every domain kind's bounding box.
  const BoundingBox unit{0, 0, 1, 1};
  Disagreements disagreements;
  for (size_t n : sizes) {
    SizeResults results;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      const Dataset dataset = MakeDataset(o, n, seed);
      ASSIGN_OR_RETURN(std::unique_ptr<Triangulation> t,
                       Triangulation::Build(dataset));
      RETURN_IF_ERROR(CheckServesConstraints(dataset, *t));
      for (WorkloadKind kind : workloads) {
        const size_t measured =
            kind == WorkloadKind::kDrift ? o.drift_queries : o.measured;
        Stream stream{kind,
                      WorkloadQueries(kind, unit, o.warmup + measured,
                                      seed * 7919 + static_cast<int>(kind)),
                      {}};
        if (o.verify) {
          for (const Point2& q : stream.queries) {
            stream.references.push_back(t->ReferenceLocate(q));
          }
        }
        for (const std::string& strategy : StrategyNames()) {
          RETURN_IF_ERROR(
              RunStream(o, *t, strategy, stream, &results, &disagreements));
        }
      }
    }
    for (WorkloadKind kind : workloads) {
      for (const std::string& strategy : StrategyNames()) {
        const Key key(std::string(WorkloadName(kind)), strategy);
        const CostSums& sums = results.sums[key];
        report->Add(
            BenchRow{mode, key.first, n, key.second, sums.mean_cost(),
                     sums.mean_faces(), sums.mean_comparisons(), 0,
                     static_cast<size_t>(results.bytes[key] / o.seeds)});
      }
    }
    if (n != sizes.back()) continue;
    for (const auto& [strategy, windows] : results.drift) {
      if (strategy == "walk") continue;
      for (const auto& [begin, sums] : windows) {
        report->Add(BenchRow{"drift", "drift@" + std::to_string(begin), n,
                             strategy, sums.mean_cost(), sums.mean_faces(),
                             sums.mean_comparisons(), 0, 0});
      }
    }
  }
  if (disagreements.count == 0) return Status::OK();
  return Status::Internal(std::to_string(disagreements.count) +
                          " answers disagree with CGAL's locate(); the first:" +
                          disagreements.first);
}

}  // namespace locator::bench
