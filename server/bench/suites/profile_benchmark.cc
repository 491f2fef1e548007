#include "server/bench/suites/profile_benchmark.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <random>
#include <vector>

#include "common/status_macros.h"
#include "locator/engine.h"
#include "server/bench/datasets/surface_terrain.h"
#include "server/bench/stopwatch.h"

namespace locator::bench {
namespace {

StatusOr<std::unique_ptr<Engine>> BuildTerrain(
    const SurfaceBenchOptions& options) {
  // The default strategy, self-tuning, as locatord serves.
  return Engine::Create(TerrainDataset(options.points, 42), EngineOptions());
}

// A random polyline inside the terrain's box whose segments add up to
// `length`, each at most 2.5 km (from any point of the box some direction
// has that much room).
std::vector<Point2> RandomLine(double length, std::mt19937_64& random) {
  const BoundingBox box = TerrainBox();
  std::uniform_real_distribution<double> u(0.05, 0.95);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  std::vector<Point2> line = {{box.min_x + u(random) * box.width(),
                               box.min_y + u(random) * box.height()}};
  for (double left = length; left > 0;) {
    const double step = std::min(left, 2500.0);
    for (;;) {
      const double a = angle(random);
      const Point2 next{line.back().x + step * std::cos(a),
                        line.back().y + step * std::sin(a)};
      if (box.Inflated(-0.01).Contains(next)) {
        line.push_back(next);
        break;
      }
    }
    left -= step;
  }
  return line;
}

}  // namespace

Status RunProfileBenchmark(const SurfaceBenchOptions& options,
                           std::ostream& out) {
  ASSIGN_OR_RETURN(const std::unique_ptr<Engine> engine, BuildTerrain(options));
  // Mean triangle edges crossed per metre of line, for uniform points.
  const double per_metre =
      1.4 * std::sqrt(static_cast<double>(options.points)) / 10000;
  out << "profile benchmark: " << options.points << " points, single thread\n"
      << "target crossings | lines | mean crossings | breakpoints/s | "
         "us per line\n";
  std::mt19937_64 random(7);
  ProfileOptions profile_options;
  profile_options.max_faces = 100'000'000;
  for (const double target : {1e1, 1e2, 1e3, 1e4, 1e5}) {
    const int lines = static_cast<int>(std::clamp(2e6 / target, 20.0, 2e4));
    std::vector<std::vector<Point2>> polylines;
    for (int i = 0; i < lines; ++i) {
      polylines.push_back(RandomLine(target / per_metre, random));
    }
    uint64_t breakpoints = 0, crossings = 0;
    Profile profile;
    const Stopwatch watch;
    for (const std::vector<Point2>& line : polylines) {
      RETURN_IF_ERROR(engine->TraceProfile(line, profile_options, &profile));
      breakpoints += profile.breakpoints.size();
      crossings += profile.crossings;
    }
    const double seconds = watch.Seconds();
    out << std::fixed << std::setprecision(0) << std::setw(16) << target
        << " | " << std::setw(5) << lines << " | " << std::setw(14)
        << static_cast<double>(crossings) / lines << " | " << std::setw(13)
        << breakpoints / seconds << " | " << std::setprecision(1)
        << std::setw(11) << seconds / lines * 1e6 << "\n";
  }
  return Status::OK();
}

Status RunInterpolationBenchmark(const SurfaceBenchOptions& options,
                                 std::ostream& out) {
  ASSIGN_OR_RETURN(const std::unique_ptr<Engine> engine, BuildTerrain(options));
  // Uniform points in random order: the locate costs what a map's random
  // clicks cost; the raster below shows the interpolation almost alone.
  const std::vector<Point2> queries = TerrainPoints(options.queries, 9);
  out << "interpolation benchmark: " << options.points << " points, "
      << options.queries << " random queries and a 1024 x 1024 raster, "
      << "single thread\n"
      << "method           | ns per located point | relative | "
         "ns per raster cell | relative\n";
  const RasterSpec raster{.box = TerrainBox(), .width = 1024, .height = 1024};
  std::vector<double> cells(raster.cells());
  double linear_point_ns = 0, linear_cell_ns = 0;
  std::vector<LocateResult> results;
  for (const Interpolation how :
       {Interpolation::kLinear, Interpolation::kNearest,
        Interpolation::kNaturalNeighbor}) {
    // Two passes; the second is timed (the first warms the tuning).
    double point_ns = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const Stopwatch watch;
      RETURN_IF_ERROR(engine->LocateBatch(queries, &results, nullptr, how));
      point_ns = watch.Seconds() * 1e9 / queries.size();
    }
    RasterSpec spec = raster;
    spec.interpolation = how;
    const Stopwatch watch;
    RETURN_IF_ERROR(engine->RenderRows(spec, 0, spec.height, cells.data()));
    const double cell_ns = watch.Seconds() * 1e9 / spec.cells();
    if (how == Interpolation::kLinear) {
      linear_point_ns = point_ns;
      linear_cell_ns = cell_ns;
    }
    out << std::left << std::setw(16) << InterpolationName(how) << std::right
        << " | " << std::fixed << std::setprecision(0) << std::setw(20)
        << point_ns << " | " << std::setprecision(2) << std::setw(8)
        << point_ns / linear_point_ns << " | " << std::setprecision(0)
        << std::setw(18) << cell_ns << " | " << std::setprecision(2)
        << cell_ns / linear_cell_ns << "\n";
  }
  return Status::OK();
}

}  // namespace locator::bench
