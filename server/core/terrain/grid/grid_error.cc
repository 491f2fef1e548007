#include "server/core/terrain/grid/grid_error.h"

#include <cmath>
#include <cstddef>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "server/core/geometry/barycentric.h"
#include "server/core/terrain/grid/grid_raster.h"

namespace locator {

namespace {

// |plane(x) - sample|, the plane base + gx * x.
inline double PlaneError(double base, double gx, int64_t x, float sample) {
  return std::abs(base + gx * static_cast<double>(x) - sample);
}

#if defined(__x86_64__)
// WorstInRun four samples at a time, each lane keeping its own first worst
// and the lanes merged by error, then column: the same errors to the bit (the
// same operations in the same order, no fused multiply-add) and the same
// sample.
__attribute__((target("avx2"))) RunWorst WorstInRunAvx2(
    const float* row, int64_t first, int64_t last, double base, double gx) {
  const __m256d sign = _mm256_set1_pd(-0.0);
  const __m256d base4 = _mm256_set1_pd(base);
  const __m256d gx4 = _mm256_set1_pd(gx);
  const __m256d four = _mm256_set1_pd(4);
  __m256d xs = _mm256_setr_pd(
      static_cast<double>(first), static_cast<double>(first + 1),
      static_cast<double>(first + 2), static_cast<double>(first + 3));
  __m256d worst4 = _mm256_setzero_pd();
  __m256d worst_x4 = _mm256_set1_pd(-1);
  int64_t x = first;
  for (; x + 3 <= last; x += 4) {
    const __m256d samples = _mm256_cvtps_pd(_mm_loadu_ps(row + x));
    const __m256d plane = _mm256_add_pd(base4, _mm256_mul_pd(gx4, xs));
    const __m256d error = _mm256_andnot_pd(sign, _mm256_sub_pd(plane, samples));
    // Ordered: a NaN error is never greater.
    const __m256d beats = _mm256_cmp_pd(error, worst4, _CMP_GT_OQ);
    worst4 = _mm256_blendv_pd(worst4, error, beats);
    worst_x4 = _mm256_blendv_pd(worst_x4, xs, beats);
    xs = _mm256_add_pd(xs, four);
  }
  alignas(32) double errors[4], columns[4];
  _mm256_store_pd(errors, worst4);
  _mm256_store_pd(columns, worst_x4);
  RunWorst worst;
  for (int lane = 0; lane < 4; ++lane) {
    const auto column = static_cast<int64_t>(columns[lane]);
    if (errors[lane] > worst.error ||
        (errors[lane] == worst.error && errors[lane] > 0 && column < worst.x)) {
      worst = {errors[lane], column};
    }
  }
  // The tail's columns follow every lane's: only a larger error wins.
  return WorstInRun(row, x, last, base, gx, worst);
}

const bool kHasAvx2 = __builtin_cpu_supports("avx2");
#endif

}  // namespace

RunWorst WorstInRun(const float* row, int64_t first, int64_t last, double base,
                    double gx, RunWorst worst) {
  for (int64_t x = first; x <= last; ++x) {
    const double e = PlaneError(base, gx, x, row[x]);
    if (e > worst.error) worst = {e, x};
  }
  return worst;
}

RunWorst FastWorstInRun(const float* row, int64_t first, int64_t last,
                        double base, double gx) {
#if defined(__x86_64__)
  if (kHasAvx2) return WorstInRunAvx2(row, first, last, base, gx);
#endif
  return WorstInRun(row, first, last, base, gx);
}

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
    const RunWorst run = FastWorstInRun(row, first, last, base, gx);
    if (run.error > worst.error) {
      worst.error = run.error;
      worst.sample = static_cast<size_t>(y) * width + run.x;
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
