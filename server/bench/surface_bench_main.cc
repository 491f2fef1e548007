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
//   locator-surface-bench --tiles [--points 1000000] [--tiles-per-zoom 16]
//   locator-surface-bench --quantized-mesh [--points 1000000]
//
// A program that prints figures, never a test: every comparison is made
// within one run (the machine is shared and noisy).

#include <iostream>
#include <optional>
#include <string>

#include "common/flags/flag_set.h"
#include "server/bench/suites/dem_benchmark.h"
#include "server/bench/suites/grid_benchmark.h"
#include "server/bench/suites/profile_benchmark.h"
#include "server/bench/suites/quantized_mesh_benchmark.h"
#include "server/bench/suites/tile_benchmark.h"

namespace {

constexpr char kProgram[] = "locator-surface-bench";

// What one run does, as its flags say.
struct SurfaceBenchRun {
  bool grid = false;
  bool profile = false;
  bool interpolation = false;
  bool dem = false;
  bool tiles = false;
  bool quantized_mesh = false;
  locator::bench::GridBenchOptions grid_options;
  locator::bench::SurfaceBenchOptions surface_options;
  locator::bench::DemBenchOptions dem_options;
  locator::bench::TileBenchOptions tile_options;
  locator::bench::QuantizedMeshBenchOptions quantized_mesh_options;
};

// Declares the flags on `flags`, into `run`.
void AddSurfaceBenchFlags(SurfaceBenchRun* run, locator::FlagSet* flags) {
  namespace flag = locator::flag;
  constexpr uint64_t kNoMax = flag::kMaxOf<int>;
  locator::bench::DemBenchOptions& dem = run->dem_options;
  locator::bench::GridBenchOptions& grid = run->grid_options;
  flags->Add("grid", flag::Switch(&run->grid),
             "locator against gdal_grid -a linear, end to end");
  flags->Add("profile", flag::Switch(&run->profile),
             "breakpoints per second for lines of 10..10^5 crossings");
  flags->Add("interpolation", flag::Switch(&run->interpolation),
             "ns per point: linear, nearest, natural neighbour");
  flags->Add("dem", flag::Switch(&run->dem),
             "TIN builds of fractal DEMs, in hmm's shape");
  flags->Add("tiles", flag::Switch(&run->tiles),
             "ms per 256x256 terrain tile (PROJ, walk, PNG) and hillshade "
             "tile by zoom");
  flags->Add("quantized-mesh", flag::Switch(&run->quantized_mesh),
             "ms per Cesium terrain tile by level");
  flags->Add("tiles-per-zoom", flag::Count(&run->tile_options.tiles, 1, 1024),
             "--tiles: tiles rendered per zoom");
  flags->Add("dem-sizes", flag::Counts(&dem.sizes, 2, 1u << 16),
             "--dem: DEM widths (= heights)");
  flags->Add("dem-errors", flag::Numbers(&dem.errors, 0, /*above=*/true),
             "--dem: errors as fractions of the height range");
  flags->Add("dem-repeats", flag::Count(&dem.repeats, 1, kNoMax),
             "--dem: builds per thread count (the best counts)");
  flags->Add("dem-reference",
             flag::Choice(
                 &dem.reference,
                 {{"1", true}, {"0", false}, {"true", true}, {"false", false}}),
             "--dem: run the reference greedy insertion too");
  flags->Add("points", flag::Count(&run->surface_options.points, 3, kNoMax),
             "terrain points");
  flags->Add("size", flag::Count(&grid.size, 1, 1u << 16),
             "--grid: raster width and height");
  flags->Add("repeats", flag::Count(&grid.repeats, 1, kNoMax),
             "--grid: end-to-end runs of each tool");
  flags->Add("threads", flag::Count(&grid.threads, 1, 1024),
             "--grid: threads of both tools");
  flags->Add("work-dir", flag::Text(&grid.work_dir).Shape("DIR"),
             "--grid: where the inputs and rasters go");
  flags->Add("queries", flag::Count(&run->surface_options.queries, 1, kNoMax),
             "--interpolation: points located per method");
}

}  // namespace

int main(int argc, char** argv) {
  SurfaceBenchRun run;
  locator::FlagSet flags(
      "Usage: locator-surface-bench "
      "--grid|--profile|--interpolation|--dem|--tiles|--quantized-mesh "
      "[flags]\n\n"
      "Grid, profile and interpolation benchmarks: figures, not tests.");
  AddSurfaceBenchFlags(&run, &flags);
  locator::Status parsed = flags.Parse(argc, argv);
  if (parsed.ok() && !flags.help_requested() && !run.grid && !run.profile &&
      !run.interpolation && !run.dem && !run.tiles && !run.quantized_mesh) {
    parsed = locator::Status::InvalidArgument(
        "give --grid, --profile, --interpolation, --dem, --tiles or "
        "--quantized-mesh");
  }
  if (std::optional<int> exit_code = locator::ExitCodeForFlags(
          kProgram, parsed, flags.help_requested() ? flags.Help() : "")) {
    return *exit_code;
  }
  run.grid_options.points = run.surface_options.points;
  run.tile_options.points = run.surface_options.points;
  run.quantized_mesh_options.points = run.surface_options.points;
  locator::Status result;
  if (run.grid) {
    result = locator::bench::RunGridBenchmark(run.grid_options, std::cout);
  }
  if (result.ok() && run.profile) {
    result =
        locator::bench::RunProfileBenchmark(run.surface_options, std::cout);
  }
  if (result.ok() && run.interpolation) {
    result = locator::bench::RunInterpolationBenchmark(run.surface_options,
                                                       std::cout);
  }
  if (result.ok() && run.dem) {
    result = locator::bench::RunDemBenchmark(run.dem_options, std::cout);
  }
  if (result.ok() && run.tiles) {
    result = locator::bench::RunTileBenchmark(run.tile_options, std::cout);
  }
  if (result.ok() && run.quantized_mesh) {
    result = locator::bench::RunQuantizedMeshBenchmark(
        run.quantized_mesh_options, std::cout);
  }
  if (!result.ok()) {
    std::cerr << kProgram << ": " << result.ToString() << "\n";
    return 1;
  }
  return 0;
}
