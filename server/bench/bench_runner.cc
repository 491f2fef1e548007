#include "server/bench/bench_runner.h"

#include <algorithm>
#include <chrono>

namespace locator::bench {

void LocateAll(const PointLocator& locator, std::span<const Point2> queries,
               CostSums* sums) {
  LocateResult r;
  for (const Point2& q : queries) {
    locator.Locate(q, &r);
    if (sums) sums->Add(r.cost);
  }
}

double MedianNsPerQuery(std::span<const Point2> queries, int repeats,
                        const std::function<void(const Point2&)>& locate) {
  std::vector<double> runs;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    for (const Point2& q : queries) locate(q);
    const std::chrono::duration<double, std::nano> took =
        std::chrono::steady_clock::now() - start;
    runs.push_back(took.count() / static_cast<double>(queries.size()));
  }
  std::sort(runs.begin(), runs.end());
  return runs[runs.size() / 2];
}

}  // namespace locator::bench
