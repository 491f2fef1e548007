// The checks every triangulation build makes on its input and output, with
// one wording for each failure whichever builder finds it (Triangulation::Build
// or the tiled build, tiled_build.h).
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_TILING_BUILD_CHECKS_H_
#define LOCATOR_CORE_TILING_BUILD_CHECKS_H_

#include <cstddef>
#include <span>

#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

// InvalidArgument naming the first point with a non-finite coordinate, or
// saying that `values` (the number of values; 0 for none) does not match
// the number of points.
Status CheckPointCoordinates(std::span<const Point2> points, size_t values);

// InvalidArgument unless `distinct` points, not `all_collinear`, can be
// triangulated: at least 3 of them, not all on one line.
Status CheckTriangulable(size_t distinct, bool all_collinear);

// InvalidArgument unless a serving mesh can index `vertices` vertices and
// `faces` faces (ServingMesh::kMaxElements each).
Status CheckMeshSize(size_t vertices, size_t faces);

// Whether all of `points` lie on one line (exactly; true for fewer than 3).
// Precondition: points[0] and points[1] differ, when there are two.
bool AllCollinear(std::span<const Point2> points);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_BUILD_CHECKS_H_
