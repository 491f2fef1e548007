#include "server/core/surface/surface_value.h"

#include <array>
#include <string>
#include <vector>

#include "server/core/geometry/barycentric.h"
#include "server/core/geometry/natural_neighbor.h"
#include "server/core/geometry/wide_math.h"

namespace locator {
namespace {

double LinearValue(const ServingMesh& mesh, uint32_t f, const Point2& q) {
  const std::array<double, 3> b =
      Barycentric(mesh.CornerPoint(f, 0), mesh.CornerPoint(f, 1),
                  mesh.CornerPoint(f, 2), q);
  return mesh.CornerValue(f, b);
}

// The squared distances are in Wide: in double, every corner would be at
// distance inf from a q 1e160 away, and the nearest lost.
double NearestValue(const ServingMesh& mesh, uint32_t f, const Point2& q) {
  int best = 0;
  Wide best_distance = -1;
  for (int i = 0; i < 3; ++i) {
    const Wide d = SquaredDistanceWide(mesh.CornerPoint(f, i), q);
    const bool nearer =
        best_distance < 0 || d < best_distance ||
        (d == best_distance && mesh.PublicId(mesh.Corner(f, i)) <
                                   mesh.PublicId(mesh.Corner(f, best)));
    if (nearer) {
      best = i;
      best_distance = d;
    }
  }
  return mesh.arrays().values[mesh.Corner(f, best)];
}

double NaturalNeighborValue(const ServingMesh& mesh, uint32_t f,
                            const Point2& q) {
  thread_local std::vector<NaturalNeighbor> neighbors;
  // q is in the closed triangle f, so inside the closed hull: Sibson's
  // coordinates exist (but for the degenerate case SibsonCoordinates
  // allows, where the linear value is the best at hand).
  if (!SibsonCoordinates(mesh, f, q, &neighbors)) {
    return LinearValue(mesh, f, q);
  }
  ConvexSum value;
  for (const NaturalNeighbor& n : neighbors) {
    value.Add(n.weight, mesh.arrays().values[n.vertex]);
  }
  return value.value();
}

}  // namespace

Status CheckInterpolation(uint64_t constraints, Interpolation how) {
  if (how == Interpolation::kNaturalNeighbor && constraints > 0) {
    return Status::InvalidArgument(
        "natural-neighbor interpolation needs a Delaunay triangulation, and "
        "this dataset has " +
        std::to_string(constraints) +
        " constrained segments (breaklines, a domain or a mesh); use linear "
        "or nearest");
  }
  return Status::OK();
}

double ValueAt(const ServingMesh& mesh, uint32_t f, const Point2& q,
               Interpolation how) {
  switch (how) {
    case Interpolation::kNaturalNeighbor:
      return NaturalNeighborValue(mesh, f, q);
    case Interpolation::kNearest:
      return NearestValue(mesh, f, q);
    case Interpolation::kLinear:
      break;
  }
  return LinearValue(mesh, f, q);
}

}  // namespace locator
