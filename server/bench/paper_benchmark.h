// RunPaper: reproduces the paper's Tables 1-4 (and adds uniform, mixed and
// drift workloads): uniform points in the unit square at n = 10K..50K step
// 5K, each workload warmed up, then measured; means over several seeds.

#ifndef LOCATOR_SERVER_BENCH_PAPER_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_PAPER_BENCHMARK_H_

#include <cstddef>
#include <vector>

#include "common/status.h"
#include "server/bench/bench_report.h"
#include "server/core/tuning_options.h"

namespace locator::bench {

struct PaperOptions {
  std::vector<size_t> sizes;  // empty: the paper's 10K..50K
  int seeds = 5;
  size_t warmup = 2000;
  size_t measured = 1000;
  // drift: queries measured after the warm-up, in windows of drift_window;
  // windows are reported for the largest n.
  size_t drift_queries = 20000;
  size_t drift_window = 500;
  TuningOptions tuning;
};

// Adds the tables' rows to `report`; the first failure to build a
// triangulation or a locator, if any.
Status RunPaper(const PaperOptions& options, BenchReport* report);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_PAPER_BENCHMARK_H_
