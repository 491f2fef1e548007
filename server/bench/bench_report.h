// BenchRow and BenchReport: the figures locator-bench prints, one row per
// figure, in CSV (machine-readable) or Markdown (for the README).
//
// CSV header: mode,workload,n,strategy,mean_cost,mean_faces,
// mean_comparisons,ns_per_query,extra_bytes,retunes_per_1e6,tune_cpu_share,
// p50_ns,p999_ns,batch_ns_per_query,full_ns_per_query (the last six are
// --scale figures, 0 where not measured). Mode is "paper",
// "paper-<domain kind>" (cdt, mesh, aniso: the paper's setting on a
// non-Delaunay triangulation), "drift"
// (workload "drift@<first query of the 500-query window>"), "scale", or
// "build" (ns_per_query then holds the build time in ns, extra_bytes the
// structure's bytes).

#ifndef LOCATOR_SERVER_BENCH_BENCH_REPORT_H_
#define LOCATOR_SERVER_BENCH_BENCH_REPORT_H_

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace locator::bench {

struct BenchRow {
  std::string mode;
  std::string workload;
  size_t n = 0;
  std::string strategy;
  double mean_cost = 0;
  double mean_faces = 0;
  double mean_comparisons = 0;
  // --scale: a Locate() answering what CGAL's rows answer (location type,
  // triangle and vertices: Detail::kLocation); 0 when not timed.
  double ns_per_query = 0;
  size_t extra_bytes = 0;
  // Re-tunes per 10^6 located queries, and the share of the timed wall
  // time spent inside re-tunes (TuningSummary::tune_nanos).
  double retunes_per_million = 0;
  double tune_cpu_share = 0;
  // Sampled single-locate latency (SampleLatency), ns per point of one
  // LocateMany() over the same queries (both Detail::kLocation), and ns per
  // Locate() with the full answer (barycentrics and value too).
  double p50_ns = 0;
  double p999_ns = 0;
  double batch_ns_per_query = 0;
  double full_ns_per_query = 0;
};

class BenchReport {
 public:
  void Add(BenchRow row) { rows_.push_back(std::move(row)); }
  const std::vector<BenchRow>& rows() const { return rows_; }

  void PrintCsv(std::ostream& out) const;
  // Tables per mode: the paper comparison, drift windows, scale timings.
  void PrintMarkdown(std::ostream& out) const;

 private:
  void PrintPaperTables(std::ostream& out) const;
  // The tables of one paper mode ("paper" or "paper-<domain kind>").
  void PrintPaperTables(const std::string& mode, std::ostream& out) const;
  void PrintDriftTable(std::ostream& out) const;
  void PrintScaleTables(std::ostream& out) const;
  // The row for (mode, workload, n, strategy), or nullptr.
  const BenchRow* Find(const std::string& mode, const std::string& workload,
                       size_t n, const std::string& strategy) const;

  std::vector<BenchRow> rows_;
};

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_BENCH_REPORT_H_
