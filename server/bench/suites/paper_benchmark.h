// RunPaper: reproduces the paper's Tables 1-4 (and adds uniform, mixed and
// drift workloads): uniform points in the unit square at n = 10K..50K step
// 5K, each workload warmed up, then measured; means over several seeds.
//
// With a domain kind (domain_datasets.h) it answers the paper's open
// question instead: the same sizes, seeds and strategies on that kind of
// non-Delaunay triangulation, for the paper's four workloads plus uniform,
// drawn in the domain's bounding box, the unit square (queries in holes or
// outside the boundary count like any other). Rows then have mode
// "paper-<kind>".

#ifndef LOCATOR_SERVER_BENCH_PAPER_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_PAPER_BENCHMARK_H_

#include <cstddef>
#include <optional>
#include <vector>

#include "locator/status.h"
#include "locator/tuning_options.h"
#include "server/bench/bench_report.h"
#include "server/bench/datasets/domain_datasets.h"

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
  // Unset: uniform points (the paper's setting).
  std::optional<DomainKind> domain;
  // Check every answer (warm-up and measured) against CGAL's own locate()
  // on the same triangulation.
  bool verify = false;
};

// Adds the rows to *report. Fails on the first triangulation or locator
// that cannot be built; with options.verify, returns Internal naming the
// first disagreements (query, strategy, both answers) if any answer
// disagrees (the rows are added either way).
Status RunPaper(const PaperOptions& options, BenchReport* report);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_PAPER_BENCHMARK_H_
