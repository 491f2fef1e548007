// locator-bench: in-process benchmark of the point-location strategies.
//
//   locator-bench --paper [--format csv|md] [--seeds 5] [--budget 64KiB]
//                 [--domain cdt|mesh|aniso] [--verify]
//   locator-bench --scale [--big] [--format csv|md] [--queries 100000]
//                 [--workloads raster,1-cluster] [--strategies self-tuning]
//   locator-bench --build [--sizes 1000000] [--threads 1,2] [--repeats 3]
//                 [--verify] [--format csv|md]
//
//   locator-bench --tiled DIR/manifest.json [--queries 100000]
//
// --build times points in memory to a mesh ready to serve: today's CGAL
// build against the tiled build on each thread count (build_benchmark.h).
//
// --tiled serves a tile set locator-build wrote (its mesh file mapped) from
// a cold page cache: ready time, uniform locates first and warm, a hot
// region against the same region in RAM, resident memory
// (tileset_benchmark.h).
//
// --scale runs the workloads of common/workload.h plus `raster` (a row-major
// grid of queries over the bounding box, in row order) on uniform points,
// and `clusters-data` (queries near the points), `clusters-raster` and
// `clusters-sparse` (uniform over the parts of the box holding at most a
// tenth of the mean density) on a non-uniform dataset (clusters:<n>:20:1),
// and `dem-uniform` and
// `dem-raster` on the TIN of a fractal DEM with n vertices (a simplified
// DEM, served as a mesh given as triangles). ns_per_query times what CGAL's
// rows answer: the location (type, triangle, vertices), without
// barycentrics or value, which full_ns_per_query adds. Its rows also give
// re-tunes per 10^6 located queries and the tuner's share of the timed wall
// time (from the first timed locate to the last), the single-locate p50
// and p99.9 (every query of one pass timed), and batch_ns_per_query: ns per
// point of one LocateMany() over the same queries, in-process. Beside the
// uniform workload, `random-reads` is the floor: four dependent reads of
// random words in a buffer as large as the serving mesh per query.
//
// A program that prints figures, never a test: compare strategies within one
// run (the machine is shared and noisy).

#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "common/flags/flag_set.h"
#include "server/bench/bench_report.h"
#include "server/bench/suites/build_benchmark.h"
#include "server/bench/suites/paper_benchmark.h"
#include "server/bench/suites/scale_benchmark.h"
#include "server/bench/suites/tileset_benchmark.h"

namespace {

constexpr char kProgram[] = "locator-bench";

// What one run does, as its flags say.
struct BenchRun {
  bool paper = false;
  bool scale = false;
  bool build = false;
  bool big = false;
  bool verify = false;
  bool csv = false;
  std::vector<size_t> sizes;  // empty: each mode's own
  locator::bench::PaperOptions paper_options;
  locator::bench::ScaleOptions scale_options;
  locator::bench::BuildOptions build_options;
  locator::bench::TileSetBenchOptions tileset_options;
};

// Declares the flags on `flags`, into `run`.
void AddBenchFlags(BenchRun* run, locator::FlagSet* flags) {
  namespace flag = locator::flag;
  constexpr uint64_t kNoMax = flag::kMaxOf<int>;
  flags->Add("paper", flag::Switch(&run->paper),
             "reproduce the paper's Tables 1-4 (+ uniform, mixed, drift)");
  flags->Add("scale", flag::Switch(&run->scale),
             "ns per locate at n = 100K and 1M vs CGAL");
  flags->Add("build", flag::Switch(&run->build),
             "seconds to a mesh ready to serve: CGAL vs tiled (n = 1M)");
  flags->Add("tiled", flag::Text(&run->tileset_options.manifest),
             "serving the tile set DIR/manifest.json (locator-build); its hot "
             "region against the same region in RAM");
  flags->Add("threads", flag::Counts(&run->build_options.threads, 1, 1024),
             "--build: the tiled build's thread counts");
  flags->Add("big", flag::Switch(&run->big), "with --scale: also n = 4M");
  flags->Add("format", flag::Choice(&run->csv, {{"md", false}, {"csv", true}}),
             "the report's format");
  flags->Add("seeds", flag::Count(&run->paper_options.seeds, 1, kNoMax),
             "--paper: datasets per n");
  flags->Add("domain", flag::Parsed([run](std::string_view name) {
                         locator::bench::DomainKind kind;
                         locator::Status status =
                             locator::bench::ParseDomainKind(name, &kind);
                         if (status.ok()) run->paper_options.domain = kind;
                         return status;
                       }).Shape("cdt|mesh|aniso"),
             "--paper on a non-Delaunay kind");
  flags->Add("verify", flag::Switch(&run->verify),
             "--paper: check every answer against CGAL's locate(); --build: "
             "check the tiled mesh is the CGAL build's and canonical; --tiled: "
             "check the tile set against its source built in memory");
  flags->Add("sizes", flag::Counts(&run->sizes, 1, flag::kMaxOf<uint32_t>),
             "n values (default: the mode's own)");
  flags->Add("budget",
             flag::Bytes(&run->paper_options.tuning.budget_bytes, 0,
                         flag::kMaxOf<int64_t>),
             "self-tuning memory budget; 0 = 10% of the triangulation");
  flags->Add("queries", flag::Count(&run->scale_options.queries, 1, kNoMax),
             "--scale: timed queries per workload");
  flags->Add("repeats", flag::Count(&run->scale_options.repeats, 1, kNoMax),
             "--scale, --build: timing repeats, the median reported (--build: "
             "3 unless given)");
  flags->Add("workloads", flag::Texts(&run->scale_options.workloads),
             "--scale: only these workloads (default: all)");
  flags->Add("strategies", flag::Texts(&run->scale_options.strategies),
             "--scale: only these strategies (default: all; CGAL's rows "
             "always run)");
}

int RunTiled(const BenchRun& run, bool queries_given) {
  locator::bench::TileSetBenchOptions options = run.tileset_options;
  if (queries_given) options.queries = run.scale_options.queries;
  options.tuning = run.paper_options.tuning;
  options.verify = run.verify;
  const locator::Status s = locator::bench::RunTileSet(options, std::cout);
  if (!s.ok()) {
    std::cerr << kProgram << ": " << s.ToString() << "\n";
    return 1;
  }
  return 0;
}

int RunBuild(const BenchRun& run, bool repeats_given) {
  locator::bench::BuildOptions build = run.build_options;
  if (!run.sizes.empty()) build.sizes = run.sizes;
  if (repeats_given) build.repeats = run.scale_options.repeats;
  build.verify = run.verify;
  build.csv = run.csv;
  const locator::Status s = locator::bench::RunBuild(build, std::cout);
  if (!s.ok()) {
    std::cerr << kProgram << ": " << s.ToString() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  BenchRun run;
  locator::FlagSet flags(
      "Usage: locator-bench --paper|--scale|--build|--tiled MANIFEST "
      "[flags]\n\n"
      "In-process point-location benchmark: figures, not tests.");
  AddBenchFlags(&run, &flags);
  locator::Status parsed = flags.Parse(argc, argv);
  if (parsed.ok() && !flags.help_requested() && !run.paper && !run.scale &&
      !run.build && run.tileset_options.manifest.empty()) {
    parsed = locator::Status::InvalidArgument(
        "give --paper, --scale, --build or --tiled");
  }
  if (std::optional<int> exit_code = locator::ExitCodeForFlags(
          kProgram, parsed, flags.help_requested() ? flags.Help() : "")) {
    return *exit_code;
  }
  if (run.build) return RunBuild(run, flags.Given("repeats"));
  if (!run.tileset_options.manifest.empty()) {
    return RunTiled(run, flags.Given("queries"));
  }

  locator::bench::PaperOptions& paper = run.paper_options;
  locator::bench::ScaleOptions& scale = run.scale_options;
  scale.tuning.budget_bytes = paper.tuning.budget_bytes;
  paper.verify = run.verify;
  if (!run.sizes.empty()) {
    paper.sizes = scale.sizes = run.sizes;
  } else if (run.big) {
    scale.sizes.push_back(4000000);
  }
  locator::bench::BenchReport report;
  locator::Status result;
  if (run.paper) result = locator::bench::RunPaper(paper, &report);
  if (result.ok() && run.scale) {
    result = locator::bench::RunScale(scale, &report);
  }
  if (!result.ok()) {
    std::cerr << kProgram << ": " << result.ToString() << "\n";
    return 1;
  }
  if (run.csv) {
    report.PrintCsv(std::cout);
  } else {
    report.PrintMarkdown(std::cout);
  }
  return 0;
}
