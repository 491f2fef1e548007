#include "server/core/terrain/grid/triangulate_grid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "server/core/terrain/grid/grid_certificate.h"
#include "server/core/terrain/grid/grid_domain.h"
#include "server/core/terrain/grid/grid_output.h"
#include "server/core/terrain/grid/grid_refiner.h"
#include "server/core/terrain/grid/grid_tiles.h"
#include "server/core/terrain/tin_mesh.h"
#include "server/core/terrain/tin_progress.h"

namespace locator {

namespace {

// Grid coordinates up to 2^24 keep every edge function and predicate on
// them exact in 64-bit integers and doubles.
constexpr uint32_t kMaxSide = 1u << 24;

std::string SampleName(uint32_t col, uint32_t row) {
  return "sample (col " + std::to_string(col) + ", row " + std::to_string(row) +
         ")";
}

// OK if `grid` is one TriangulateGrid can read; counts its valid samples.
Status CheckGrid(const ElevationGrid& grid, uint64_t* valid) {
  const std::string size =
      std::to_string(grid.width) + " x " + std::to_string(grid.height);
  if (grid.width < 2 || grid.height < 2) {
    return Status::InvalidArgument("the grid has " + size +
                                   " samples; a TIN needs at least 2 x 2");
  }
  if (grid.width > kMaxSide || grid.height > kMaxSide) {
    return Status::InvalidArgument(
        "the grid has " + size + " samples; at most " +
        std::to_string(kMaxSide) + " on a side are supported");
  }
  if (grid.values.size() != grid.samples()) {
    return Status::InvalidArgument("the grid has " +
                                   std::to_string(grid.values.size()) +
                                   " values for " + size + " samples");
  }
  const Point2 far = grid.SampleAt(grid.width - 1, grid.height - 1);
  if (!std::isfinite(grid.origin_x) || !std::isfinite(grid.origin_y) ||
      !std::isfinite(grid.step_x) || !std::isfinite(grid.step_y) ||
      grid.step_x == 0 || grid.step_y == 0 || !IsFinite(far)) {
    return Status::InvalidArgument(
        "the grid's placement (origin " + std::to_string(grid.origin_x) + ", " +
        std::to_string(grid.origin_y) + ", step " +
        std::to_string(grid.step_x) + ", " + std::to_string(grid.step_y) +
        ") must be finite, with non-zero steps, and keep every sample "
        "finite");
  }
  // One branch-free pass counts; only a grid with an infinity is searched
  // for the first one.
  uint64_t nan = 0, infinite = 0;
  for (const float v : grid.values) {
    nan += v != v;
    infinite += std::abs(v) == std::numeric_limits<float>::infinity();
  }
  if (infinite > 0) {
    const auto first = static_cast<uint64_t>(
        std::find_if(grid.values.begin(), grid.values.end(),
                     [](float v) { return std::isinf(v); }) -
        grid.values.begin());
    return Status::InvalidArgument(
        SampleName(static_cast<uint32_t>(first % grid.width),
                   static_cast<uint32_t>(first / grid.width)) +
        " is infinite; nodata must be NaN");
  }
  *valid = grid.samples() - nan;
  return Status::OK();
}

// Greedy insertion over the whole grid on one thread, then the certificate.
Status BuildOneRegion(const ElevationGrid& grid, const CellMask& mask,
                      const TinOptions& options, TinProgressReporter* progress,
                      TinMesh* mesh) {
  const GridRegion whole{
      GridRect{0, 0, grid.width - int64_t{1}, grid.height - int64_t{1}}};
  BuildRegionMesh(mask, whole.rect, {}, mesh);
  if (options.max_points > 0 && mesh->num_vertices() > options.max_points) {
    return Status::InvalidArgument(
        "max_points is " + std::to_string(options.max_points) +
        "; the domain's boundary alone needs " +
        std::to_string(mesh->num_vertices()) + " vertices");
  }
  GridRefiner refiner(grid, mesh, GridMetric::kPlane, whole, options.max_error);
  refiner.ScanAll(1);
  return refiner.Refine(options.max_points, progress, 0);
}

}  // namespace

Status TriangulateGrid(const ElevationGrid& grid, const TinOptions& options,
                       Dataset* out, SimplificationStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  uint64_t valid = 0;
  Status s = CheckTinOptions(options);
  if (s.ok()) s = CheckGrid(grid, &valid);
  if (!s.ok()) return s;
  const CellMask mask(grid);
  if (mask.valid_cells() == 0) {
    return Status::InvalidArgument(
        "no cell of the grid has four valid corners (" + std::to_string(valid) +
        " of " + std::to_string(grid.samples()) +
        " samples are valid): there is nothing to triangulate");
  }
  *stats = SimplificationStats();
  stats->source_samples = valid;
  stats->unserved_samples = mask.unserved_samples();
  stats->target_error = options.max_error;
  stats->max_points = options.max_points;

  const uint64_t domain_samples = valid - mask.unserved_samples();
  if (options.max_error == 0 &&
      (options.max_points == 0 || options.max_points >= domain_samples)) {
    // Every served sample is a vertex, whose own value the engine answers.
    s = WriteGridCells(grid, mask, out);
  } else {
    // max_points is a budget for the whole grid: it binds on one thread.
    const unsigned threads = options.threads == 0 ? 1 : options.threads;
    const TilePlan plan =
        options.max_points == 0 ? PlanTiles(grid, threads) : TilePlan();
    TinProgressReporter progress(options, plan.tiles());
    TinMesh mesh(TinMesh::Coordinates::kGridIntegers);
    s = plan.tiles() > 1
            ? BuildTiled(grid, mask, options, plan, threads, &progress, &mesh)
            : BuildOneRegion(grid, mask, options, &progress, &mesh);
    // In row-major order the certificate's scan reads the grid in order.
    if (s.ok()) SortRowMajor(&mesh);
    const size_t built = mesh.num_vertices();
    if (s.ok()) {
      s = CertifyGridTin(grid, options, threads, &progress, &mesh,
                         &stats->max_error);
    }
    // Vertices the certificate inserted were appended.
    if (s.ok() && mesh.num_vertices() != built) SortRowMajor(&mesh);
    if (s.ok()) s = WriteGridTin(grid, mesh, out);
  }
  if (!s.ok()) return s;
  RecordTinMade(*out, start, stats);
  return Status::OK();
}

}  // namespace locator
