#include "server/bench/paper_benchmark.h"

#include <cstdio>
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
void RunStream(const PaperOptions& o, const Triangulation& t,
               const std::string& strategy, WorkloadKind kind,
               const std::vector<Point2>& queries, SizeResults* out) {
  std::unique_ptr<PointLocator> locator;
  Status s = MakePointLocator(strategy, t, o.tuning, &locator);
  if (!s.ok()) {
    std::fprintf(stderr, "locator-bench: %s\n", s.ToString().c_str());
    std::exit(1);
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
}

}  // namespace

void RunPaper(const PaperOptions& o, BenchReport* report) {
  std::vector<size_t> sizes = o.sizes;
  if (sizes.empty()) sizes.assign(kPaperSizes.begin(), kPaperSizes.end());
  const BoundingBox unit{0, 0, 1, 1};
  for (size_t n : sizes) {
    SizeResults results;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      const Dataset dataset = GenerateUniform(n, seed);
      std::unique_ptr<Triangulation> t;
      Status s = Triangulation::Build(dataset, &t);
      if (!s.ok()) {
        std::fprintf(stderr, "locator-bench: %s\n", s.ToString().c_str());
        std::exit(1);
      }
      for (WorkloadKind kind : AllWorkloadKinds()) {
        const size_t measured =
            kind == WorkloadKind::kDrift ? o.drift_queries : o.measured;
        const std::vector<Point2> queries =
            WorkloadQueries(kind, unit, o.warmup + measured,
                            seed * 7919 + static_cast<int>(kind));
        for (const std::string& strategy : StrategyNames()) {
          RunStream(o, *t, strategy, kind, queries, &results);
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
}

}  // namespace locator::bench
