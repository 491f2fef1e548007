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
  return MedianNsPerPoint(queries.size(), repeats, [&] {
    for (const Point2& q : queries) locate(q);
  });
}

double MedianNsPerPoint(size_t points, int repeats,
                        const std::function<void()>& run) {
  std::vector<double> runs;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    run();
    const std::chrono::duration<double, std::nano> took =
        std::chrono::steady_clock::now() - start;
    runs.push_back(took.count() / static_cast<double>(points));
  }
  std::sort(runs.begin(), runs.end());
  return runs[runs.size() / 2];
}

LatencySample SampleLatency(std::span<const Point2> queries,
                            const std::function<void(const Point2&)>& locate) {
  // One clock read per query: each latency runs from the read before the
  // query to the read after it, so it includes one read's cost, as a
  // separately timed call would.
  std::vector<double> ns(queries.size());
  auto before = std::chrono::steady_clock::now();
  for (size_t i = 0; i < queries.size(); ++i) {
    locate(queries[i]);
    const auto after = std::chrono::steady_clock::now();
    ns[i] = std::chrono::duration<double, std::nano>(after - before).count();
    before = after;
  }
  LatencySample sample;
  if (ns.empty()) return sample;
  std::sort(ns.begin(), ns.end());
  sample.p50_ns = ns[ns.size() / 2];
  sample.p999_ns = ns[std::min(ns.size() - 1, ns.size() * 999 / 1000)];
  return sample;
}

}  // namespace locator::bench
