// locator-surface-bench: the surface benchmarks (grid against gdal_grid,
// profiles, interpolation cost).
//
//   locator-surface-bench --grid [--points 1000000] [--size 2048]
//                         [--repeats 1] [--threads 2] [--work-dir DIR]
//   locator-surface-bench --profile [--points 1000000]
//   locator-surface-bench --interpolation [--points 1000000]
//                         [--queries 200000]
//   locator-surface-bench --dem [--dem-sizes 1187,2373,4745,9490]
//                         [--dem-errors 0.01,0.001,0.0005,0.0001]
//                         [--dem-repeats 1] [--dem-reference 1]
//
// A program that prints figures, never a test: every comparison is made
// within one run (the machine is shared and noisy).

#include <boost/program_options.hpp>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "server/bench/suites/dem_benchmark.h"
#include "server/bench/suites/grid_benchmark.h"
#include "server/bench/suites/profile_benchmark.h"

namespace po = boost::program_options;

namespace {

// Parses "a,b,c" into *out; false if an item is not a T.
template <class T>
bool ParseList(const std::string& text, std::vector<T>* out) {
  out->clear();
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    std::istringstream parse(item);
    T value;
    if (!(parse >> value) || !parse.eof()) return false;
    out->push_back(value);
  }
  return !out->empty();
}

}  // namespace

int main(int argc, char** argv) {
  po::options_description desc(
      "locator-surface-bench: grid, profile and interpolation benchmarks\n"
      "Options");
  locator::bench::GridBenchOptions grid;
  locator::bench::SurfaceBenchOptions surface;
  locator::bench::DemBenchOptions dem;
  std::string dem_sizes = "1187,2373,4745,9490";
  std::string dem_errors = "0.01,0.001,0.0005,0.0001";
  desc.add_options()("help,h", "print this help")(
      "grid", "locator against gdal_grid -a linear, end to end")(
      "profile", "breakpoints per second for lines of 10..10^5 crossings")(
      "interpolation", "ns per point: linear, nearest, natural neighbour")(
      "dem", "TIN builds of fractal DEMs, in hmm's shape")(
      "dem-sizes", po::value(&dem_sizes)->default_value(dem_sizes),
      "--dem: DEM widths (= heights), comma-separated")(
      "dem-errors", po::value(&dem_errors)->default_value(dem_errors),
      "--dem: errors as fractions of the height range")(
      "dem-repeats", po::value(&dem.repeats)->default_value(1),
      "--dem: builds per thread count (the best counts)")(
      "dem-reference", po::value(&dem.reference)->default_value(true),
      "--dem: run the reference greedy insertion too")(
      "points", po::value(&surface.points)->default_value(1000000),
      "terrain points")("size", po::value(&grid.size)->default_value(2048),
                        "--grid: raster width and height")(
      "repeats", po::value(&grid.repeats)->default_value(1),
      "--grid: end-to-end runs of each tool")(
      "threads", po::value(&grid.threads)->default_value(2),
      "--grid: threads of both tools")(
      "work-dir", po::value(&grid.work_dir)->default_value(grid.work_dir),
      "--grid: where the inputs and rasters go")(
      "queries", po::value(&surface.queries)->default_value(200000),
      "--interpolation: points located per method");
  po::variables_map vm;
  try {
    po::store(po::parse_command_line(argc, argv, desc), vm);
    po::notify(vm);
  } catch (const std::exception& e) {
    std::cerr << "locator-surface-bench: " << e.what() << "\n" << desc;
    return 2;
  }
  const bool any = vm.count("grid") || vm.count("profile") ||
                   vm.count("interpolation") || vm.count("dem");
  const bool lists =
      ParseList(dem_sizes, &dem.sizes) && ParseList(dem_errors, &dem.errors);
  if (vm.count("help") || !any || grid.repeats < 1 || grid.threads < 1 ||
      !lists || dem.repeats < 1) {
    std::cerr << desc;
    return vm.count("help") ? 0 : 2;
  }
  grid.points = surface.points;
  locator::Status run;
  if (vm.count("grid")) run = locator::bench::RunGridBenchmark(grid, std::cout);
  if (run.ok() && vm.count("profile")) {
    run = locator::bench::RunProfileBenchmark(surface, std::cout);
  }
  if (run.ok() && vm.count("interpolation")) {
    run = locator::bench::RunInterpolationBenchmark(surface, std::cout);
  }
  if (run.ok() && vm.count("dem")) {
    run = locator::bench::RunDemBenchmark(dem, std::cout);
  }
  if (!run.ok()) {
    std::cerr << "locator-surface-bench: " << run.ToString() << "\n";
    return 1;
  }
  return 0;
}
