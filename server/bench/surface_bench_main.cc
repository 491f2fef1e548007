// locator-surface-bench: the surface benchmarks (grid against gdal_grid,
// profiles, interpolation cost).
//
//   locator-surface-bench --grid [--points 1000000] [--size 2048]
//                         [--repeats 1] [--threads 2] [--work-dir DIR]
//   locator-surface-bench --profile [--points 1000000]
//   locator-surface-bench --interpolation [--points 1000000]
//                         [--queries 200000]
//
// A program that prints figures, never a test: every comparison is made
// within one run (the machine is shared and noisy).

#include <boost/program_options.hpp>
#include <iostream>
#include <string>

#include "server/bench/grid_benchmark.h"
#include "server/bench/profile_benchmark.h"

namespace po = boost::program_options;

int main(int argc, char** argv) {
  po::options_description desc(
      "locator-surface-bench: grid, profile and interpolation benchmarks\n"
      "Options");
  locator::bench::GridBenchOptions grid;
  locator::bench::SurfaceBenchOptions surface;
  desc.add_options()("help,h", "print this help")(
      "grid", "locator against gdal_grid -a linear, end to end")(
      "profile", "breakpoints per second for lines of 10..10^5 crossings")(
      "interpolation", "ns per point: linear, nearest, natural neighbour")(
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
  const bool any =
      vm.count("grid") || vm.count("profile") || vm.count("interpolation");
  if (vm.count("help") || !any || grid.repeats < 1 || grid.threads < 1) {
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
  if (!run.ok()) {
    std::cerr << "locator-surface-bench: " << run.ToString() << "\n";
    return 1;
  }
  return 0;
}
