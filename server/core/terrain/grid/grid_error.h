// The sample of a grid triangle farthest from the triangle's surface, by
// either measure greedy insertion uses (see grid_refiner.h):
//   WorstPlaneSample   the plane through the corners in grid coordinates;
//   WorstServedSample  the engine's own interpolation in dataset
//                      coordinates (Barycentric; EdgeBarycentric on an
//                      edge), with the corners in the order the output
//                      lists them.
// Corners are never the answer: they are vertices, exact by construction.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_TERRAIN_GRID_ERROR_H_
#define LOCATOR_CORE_TERRAIN_GRID_ERROR_H_

#include <array>
#include <cstdint>

#include "common/elevation_grid.h"
#include "server/core/terrain/grid/grid_domain.h"

namespace locator {

struct WorstSample {
  static constexpr uint64_t kNone = ~uint64_t{0};
  double error = 0;
  uint64_t sample = kNone;  // index into ElevationGrid::values
};

// Whether the output lists a grid triangle's corners in another order than
// the mesh: the grid-to-dataset transform mirrors when step_x * step_y < 0,
// and the output is counter-clockwise in dataset coordinates.
inline bool OutputMirrors(const ElevationGrid& grid) {
  return (grid.step_x < 0) != (grid.step_y < 0);
}

// The worst sample of the triangle `c` (counter-clockwise in grid
// coordinates), leaving out those on edge i (corner i to i + 1) when
// open[i]. error 0 and kNone if it covers no other sample.
WorstSample WorstPlaneSample(const ElevationGrid& grid,
                             const std::array<GridPoint, 3>& c,
                             std::array<bool, 3> open);

// The first sample of a run of a grid row at the run's largest plane error
// |base + gx * x - row[x]|, if that is above 0 (x = -1 otherwise).
struct RunWorst {
  double error = 0;
  int64_t x = -1;
};
// The worst sample of row[first..last] (NaN samples never count), one at a
// time: a sample whose error beats `worst` so far becomes the worst.
RunWorst WorstInRun(const float* row, int64_t first, int64_t last, double base,
                    double gx, RunWorst worst = {});
// WorstInRun(row, first, last, base, gx), four samples at a time where the
// processor has AVX2: the same errors to the bit and the same sample.
RunWorst FastWorstInRun(const float* row, int64_t first, int64_t last,
                        double base, double gx);

// The worst sample of the triangle `c` as the engine serves it.
WorstSample WorstServedSample(const ElevationGrid& grid,
                              const std::array<GridPoint, 3>& c);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_ERROR_H_
