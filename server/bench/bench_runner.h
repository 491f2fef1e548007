// Shared pieces of locator-bench's runs: query streams, cost measurement and
// timing of a PointLocator.

#ifndef LOCATOR_SERVER_BENCH_BENCH_RUNNER_H_
#define LOCATOR_SERVER_BENCH_BENCH_RUNNER_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "common/workload.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "server/core/strategies/point_locator.h"

namespace locator::bench {

// Sums of the paper's cost metric over some queries.
struct CostSums {
  double cost = 0;
  double faces = 0;
  double comparisons = 0;
  size_t queries = 0;

  void Add(const LocateCost& c) {
    cost += c.total();
    faces += c.faces_visited;
    comparisons += c.comparisons;
    ++queries;
  }
  void Add(const CostSums& o) {
    cost += o.cost;
    faces += o.faces;
    comparisons += o.comparisons;
    queries += o.queries;
  }
  double mean_cost() const { return queries ? cost / queries : 0; }
  double mean_faces() const { return queries ? faces / queries : 0; }
  double mean_comparisons() const {
    return queries ? comparisons / queries : 0;
  }
};

// Locates every query in order, adding costs to *sums (if given).
void LocateAll(const PointLocator& locator, std::span<const Point2> queries,
               CostSums* sums);

// Median over `repeats` runs of the wall-clock ns per call of
// locate(queries[i]) over all queries.
double MedianNsPerQuery(std::span<const Point2> queries, int repeats,
                        const std::function<void(const Point2&)>& locate);
// Median over `repeats` runs of run()'s wall-clock ns divided by `points`.
double MedianNsPerPoint(size_t points, int repeats,
                        const std::function<void()>& run);

// Per-query latency: one pass over the queries, each call timed with
// steady_clock. Every query counts, so that p99.9 is the 1,000th part of the
// whole pass and not the second-worst of a sample, which a single timer
// interrupt of the virtual machine decides.
struct LatencySample {
  double p50_ns = 0;
  double p999_ns = 0;
};
LatencySample SampleLatency(std::span<const Point2> queries,
                            const std::function<void(const Point2&)>& locate);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_BENCH_RUNNER_H_
