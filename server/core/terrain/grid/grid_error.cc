#include "server/core/terrain/grid/grid_error.h"

#include <cmath>
#include <cstddef>

#include "server/core/geometry/barycentric.h"
#include "server/core/terrain/grid/grid_raster.h"

namespace locator {

WorstSample WorstPlaneSample(const ElevationGrid& grid,
                             const std::array<GridPoint, 3>& c,
                             std::array<bool, 3> open) {
  std::array<double, 3> z;
  for (int i = 0; i < 3; ++i) {
    z[i] = grid.ValueAt(static_cast<uint32_t>(c[i].x),
                        static_cast<uint32_t>(c[i].y));
  }
  // The plane z = z0 + gx (x - x0) + gy (y - y0) through the corners; the
  // determinant is exact (integers) and positive (counter-clockwise).
  const double x1 = static_cast<double>(c[1].x - c[0].x);
  const double y1 = static_cast<double>(c[1].y - c[0].y);
  const double x2 = static_cast<double>(c[2].x - c[0].x);
  const double y2 = static_cast<double>(c[2].y - c[0].y);
  const double det = x1 * y2 - x2 * y1;
  const double z1 = z[1] - z[0];
  const double z2 = z[2] - z[0];
  const double gx = (z1 * y2 - z2 * y1) / det;
  const double gy = (z2 * x1 - z1 * x2) / det;
  const float* values = grid.values.data();
  const size_t width = grid.width;
  WorstSample worst;
  ForEachRun(c, open, true, [&](int64_t y, int64_t first, int64_t last) {
    const float* row = values + static_cast<size_t>(y) * width;
    const double base = z[0] + gy * static_cast<double>(y - c[0].y) -
                        gx * static_cast<double>(c[0].x);
    double best = worst.error;
    int64_t best_x = -1;
    for (int64_t x = first; x <= last; ++x) {
      const double e = std::abs(base + gx * static_cast<double>(x) - row[x]);
      if (e > best) {
        best = e;
        best_x = x;
      }
    }
    if (best_x >= 0) {
      worst.error = best;
      worst.sample = static_cast<size_t>(y) * width + best_x;
    }
  });
  return worst;
}

WorstSample WorstServedSample(const ElevationGrid& grid,
                              const std::array<GridPoint, 3>& c) {
  // Output corner k is mesh corner order[k]; mesh edge i (corner i to
  // i + 1) is output edge served_edge[i], named by its opposite corner.
  const std::array<int, 3> order = OutputMirrors(grid)
                                       ? std::array<int, 3>{0, 2, 1}
                                       : std::array<int, 3>{0, 1, 2};
  std::array<int, 3> output_index;
  for (int k = 0; k < 3; ++k) output_index[order[k]] = k;
  std::array<int, 3> served_edge;
  for (int i = 0; i < 3; ++i) served_edge[i] = output_index[(i + 2) % 3];
  std::array<Point2, 3> corners;
  std::array<double, 3> z;
  for (int k = 0; k < 3; ++k) {
    const GridPoint& p = c[order[k]];
    const auto col = static_cast<uint32_t>(p.x);
    const auto row = static_cast<uint32_t>(p.y);
    corners[k] = grid.SampleAt(col, row);
    z[k] = grid.ValueAt(col, row);
  }
  const std::array<EdgeFunction, 3> edges = {EdgeFunction(c[0], c[1]),
                                             EdgeFunction(c[1], c[2]),
                                             EdgeFunction(c[2], c[0])};
  const float* values = grid.values.data();
  const size_t width = grid.width;
  WorstSample worst;
  // Corners are skipped: the engine answers a vertex's own value.
  ForEachRun(c, {false, false, false}, true,
             [&](int64_t y, int64_t first, int64_t last) {
               const float* row = values + static_cast<size_t>(y) * width;
               for (int64_t x = first; x <= last; ++x) {
                 const Point2 q = grid.SampleAt(static_cast<uint32_t>(x),
                                                static_cast<uint32_t>(y));
                 int on_edge = -1;
                 for (int i = 0; i < 3; ++i) {
                   if (edges[i].At(x, y) == 0) on_edge = i;
                 }
                 const std::array<double, 3> b =
                     on_edge < 0
                         ? Barycentric(corners[0], corners[1], corners[2], q)
                         : EdgeBarycentric(corners, served_edge[on_edge], q);
                 double value = 0;
                 for (int k = 0; k < 3; ++k) value += b[k] * z[k];
                 const double e = std::abs(row[x] - value);
                 if (e > worst.error) {
                   worst.error = e;
                   worst.sample = static_cast<size_t>(y) * width + x;
                 }
               }
             });
  return worst;
}

}  // namespace locator
