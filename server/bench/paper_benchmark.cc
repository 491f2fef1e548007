#include "server/bench/paper_benchmark.h"

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "common/workload.h"
#include "server/bench/bench_runner.h"
#include "server/bench/paper_figures.h"
#include "server/core/dataset.h"
#include "server/core/locator_factory.h"
#include "server/core/triangulation.h"

namespace locator::bench {

namespace {

using Key = std::pair<std::string, std::string>;  // (workload, strategy)

struct SizeResults {
  std::map<Key, CostSums> sums;
  std::map<Key, double> bytes;
  // drift windows per strategy, by window start (query index)
  std::map<std::string, std::map<size_t, CostSums>> drift;
};

// Runs one strategy over one query stream: warm-up, then measurement (in
// windows for drift).
Status RunStream(const PaperOptions& o, const Triangulation& t,
                 const std::string& strategy, WorkloadKind kind,
                 const std::vector<Point2>& queries, SizeResults* out) {
  std::unique_ptr<PointLocator> locator;
  if (Status s = MakePointLocator(strategy, t, o.tuning, &locator); !s.ok()) {
    return s;
  }
  const std::span<const Point2> all(queries);
  LocateAll(*locator, all.first(o.warmup), nullptr);
  const Key key(std::string(WorkloadName(kind)), strategy);
  if (kind != WorkloadKind::kDrift) {
    LocateAll(*locator, all.subspan(o.warmup), &out->sums[key]);
  } else {
    for (size_t begin = o.warmup; begin < all.size(); begin += o.drift_window) {
      CostSums window;
      LocateAll(
          *locator,
          all.subspan(begin, std::min(o.drift_window, all.size() - begin)),
          &window);
      out->drift[strategy][begin].Add(window);
      out->sums[key].Add(window);
    }
  }
  out->bytes[key] += locator->Summary().memory_bytes;
  return Status::OK();
}

}  // namespace

Status RunPaper(const PaperOptions& o, BenchReport* report) {
  std::vector<size_t> sizes = o.sizes;
  if (sizes.empty()) sizes.assign(kPaperSizes.begin(), kPaperSizes.end());
  const BoundingBox unit{0, 0, 1, 1};
  for (size_t n : sizes) {
    SizeResults results;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      const Dataset dataset = GenerateUniform(n, seed);
      std::unique_ptr<Triangulation> t;
      if (Status s = Triangulation::Build(dataset, &t); !s.ok()) return s;
      for (WorkloadKind kind : AllWorkloadKinds()) {
        const size_t measured =
            kind == WorkloadKind::kDrift ? o.drift_queries : o.measured;
        const std::vector<Point2> queries =
            WorkloadQueries(kind, unit, o.warmup + measured,
                            seed * 7919 + static_cast<int>(kind));
        for (const std::string& strategy : StrategyNames()) {
          if (Status s = RunStream(o, *t, strategy, kind, queries, &results);
              !s.ok()) {
            return s;
          }
        }
      }
    }
    for (WorkloadKind kind : AllWorkloadKinds()) {
      for (const std::string& strategy : StrategyNames()) {
        const Key key(std::string(WorkloadName(kind)), strategy);
        const CostSums& sums = results.sums[key];
        report->Add(
            BenchRow{"paper", key.first, n, key.second, sums.mean_cost(),
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
  return Status::OK();
}

}  // namespace locator::bench
