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
  std::vector<double> ns;
  for (size_t i = 0; i < queries.size(); ++i) {
    if (i % LatencySample::kLatencyStride != 0) {
      locate(queries[i]);
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    locate(queries[i]);
    const std::chrono::duration<double, std::nano> took =
        std::chrono::steady_clock::now() - start;
    ns.push_back(took.count());
  }
  LatencySample sample;
  if (ns.empty()) return sample;
  std::sort(ns.begin(), ns.end());
  sample.p50_ns = ns[ns.size() / 2];
  sample.p999_ns = ns[std::min(ns.size() - 1, ns.size() * 999 / 1000)];
  return sample;
}

}  // namespace locator::bench
