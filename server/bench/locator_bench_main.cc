// locator-bench: in-process benchmark of the point-location strategies.
//
//   locator-bench --paper [--format csv|md] [--seeds 5] [--budget 64KiB]
//                 [--domain cdt|mesh|aniso] [--verify]
//   locator-bench --scale [--big] [--format csv|md] [--queries 100000]
//                 [--workloads raster,1-cluster] [--strategies self-tuning]
//   locator-bench --build [--sizes 1000000] [--threads 1,2] [--repeats 3]
//                 [--verify] [--format csv|md]
//
// --build times points in memory to a mesh ready to serve: today's CGAL
// build against the tiled build on each thread count (build_benchmark.h).
//
// --scale runs the workloads of common/workload.h plus `raster` (a row-major
// grid of queries over the bounding box, in row order) on uniform points,
// and `clusters-data` (queries near the points) and `clusters-raster` on a
// non-uniform dataset (clusters:<n>:20:1), and `dem-uniform` and
// `dem-raster` on the TIN of a fractal DEM with n vertices (a simplified
// DEM, served as a mesh given as triangles). ns_per_query times what CGAL's
// rows answer: the location (type, triangle, vertices), without
// barycentrics or value, which full_ns_per_query adds. Its rows also give
// re-tunes per 10^6 located queries and the tuner's share of the timed wall
// time (from the first timed locate to the last), a sampled single-locate
// p50 and p99.9 (one query in 64 timed on its own), and batch_ns_per_query:
// ns per point of one LocateMany() over the same queries, in-process.
//
// A program that prints figures, never a test: compare strategies within one
// run (the machine is shared and noisy).

#include <boost/program_options.hpp>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "server/bench/bench_report.h"
#include "server/bench/suites/build_benchmark.h"
#include "server/bench/suites/paper_benchmark.h"
#include "server/bench/suites/scale_benchmark.h"
#include "server/core/dataset/byte_size.h"

namespace po = boost::program_options;

namespace {

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  return items;
}

std::vector<size_t> ParseSizes(const std::string& text) {
  std::vector<size_t> sizes;
  for (const std::string& item : SplitList(text)) {
    sizes.push_back(std::stoul(item));
  }
  return sizes;
}

}  // namespace

int main(int argc, char** argv) {
  po::options_description desc(
      "locator-bench: in-process point-location benchmark\nOptions");
  std::string format = "md", budget, sizes, domain, workloads, strategies,
              threads = "1,2";
  locator::bench::PaperOptions paper;
  locator::bench::ScaleOptions scale;
  desc.add_options()("help,h", "print this help")(
      "paper", "reproduce the paper's Tables 1-4 (+ uniform, mixed, drift)")(
      "scale", "ns per locate at n = 100K and 1M vs CGAL")(
      "build", "seconds to a mesh ready to serve: CGAL vs tiled (n = 1M)")(
      "threads", po::value(&threads)->default_value("1,2"),
      "--build: the tiled build's thread counts, comma-separated")(
      "big", "with --scale: also n = 4M")(
      "format", po::value(&format)->default_value("md"), "csv | md")(
      "seeds", po::value(&paper.seeds)->default_value(5),
      "--paper: datasets per n")(
      "domain", po::value(&domain),
      "--paper on a non-Delaunay kind: cdt | mesh | aniso")(
      "verify",
      "--paper: check every answer against CGAL's locate(); --build: check "
      "the tiled mesh is the CGAL build's and canonical")(
      "sizes", po::value(&sizes),
      "comma-separated n values (default: the mode's own)")(
      "budget", po::value(&budget),
      "self-tuning memory budget, e.g. 64KiB (default 10% of the "
      "triangulation)")("queries",
                        po::value(&scale.queries)->default_value(100000),
                        "--scale: timed queries per workload")(
      "repeats", po::value(&scale.repeats)->default_value(5),
      "--scale, --build: timing repeats (median reported; --build: 3 unless "
      "given)")(
      "workloads", po::value(&workloads),
      "--scale: only these workloads, comma-separated (default: all)")(
      "strategies", po::value(&strategies),
      "--scale: only these strategies, comma-separated (default: all; "
      "CGAL's rows always run)");
  po::variables_map vm;
  try {
    po::store(po::parse_command_line(argc, argv, desc), vm);
    po::notify(vm);
  } catch (const std::exception& e) {
    std::cerr << "locator-bench: " << e.what() << "\n" << desc;
    return 2;
  }
  if (vm.count("help") ||
      (!vm.count("paper") && !vm.count("scale") && !vm.count("build")) ||
      (format != "csv" && format != "md")) {
    std::cerr << desc;
    return vm.count("help") ? 0 : 2;
  }
  if (!budget.empty()) {
    locator::Status s =
        locator::ParseByteSize(budget, &paper.tuning.budget_bytes);
    if (!s.ok()) {
      std::cerr << "locator-bench: " << s.message() << "\n";
      return 2;
    }
    scale.tuning.budget_bytes = paper.tuning.budget_bytes;
  }
  if (!domain.empty()) {
    locator::bench::DomainKind kind;
    locator::Status s = locator::bench::ParseDomainKind(domain, &kind);
    if (!s.ok()) {
      std::cerr << "locator-bench: " << s.message() << "\n";
      return 2;
    }
    paper.domain = kind;
  }
  paper.verify = vm.count("verify") > 0;
  scale.workloads = SplitList(workloads);
  scale.strategies = SplitList(strategies);
  if (!sizes.empty()) {
    try {
      paper.sizes = scale.sizes = ParseSizes(sizes);
    } catch (const std::exception&) {
      std::cerr << "locator-bench: bad --sizes '" << sizes << "'\n";
      return 2;
    }
  } else if (vm.count("big")) {
    scale.sizes.push_back(4000000);
  }

  if (vm.count("build")) {
    locator::bench::BuildOptions build;
    try {
      if (!sizes.empty()) build.sizes = ParseSizes(sizes);
      build.threads.clear();
      for (const size_t t : ParseSizes(threads)) {
        if (t == 0) throw std::invalid_argument("0 threads");
        build.threads.push_back(static_cast<unsigned>(t));
      }
    } catch (const std::exception&) {
      std::cerr << "locator-bench: bad --sizes '" << sizes << "' or --threads '"
                << threads << "'\n";
      return 2;
    }
    if (!vm["repeats"].defaulted()) build.repeats = scale.repeats;
    build.verify = vm.count("verify") > 0;
    build.csv = format == "csv";
    const locator::Status s = locator::bench::RunBuild(build, std::cout);
    if (!s.ok()) {
      std::cerr << "locator-bench: " << s.ToString() << "\n";
      return 1;
    }
    return 0;
  }

  locator::bench::BenchReport report;
  locator::Status run;
  if (vm.count("paper")) run = locator::bench::RunPaper(paper, &report);
  if (run.ok() && vm.count("scale")) {
    run = locator::bench::RunScale(scale, &report);
  }
  if (!run.ok()) {
    std::cerr << "locator-bench: " << run.ToString() << "\n";
    return 1;
  }
  if (format == "csv") {
    report.PrintCsv(std::cout);
  } else {
    report.PrintMarkdown(std::cout);
  }
  return 0;
}
