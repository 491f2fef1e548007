#include "server/core/surface_value.h"

#include <array>
#include <string>
#include <vector>

#include "server/core/barycentric.h"
#include "server/core/natural_neighbor.h"

namespace locator {
namespace {

double LinearValue(const ServingMesh& mesh, uint32_t f, const Point2& q) {
  const std::array<double, 3> b =
      Barycentric(mesh.CornerPoint(f, 0), mesh.CornerPoint(f, 1),
                  mesh.CornerPoint(f, 2), q);
  double value = 0;
  for (int i = 0; i < 3; ++i) {
    value += b[i] * mesh.arrays().values[mesh.Corner(f, i)];
  }
  return value;
}

double NearestValue(const ServingMesh& mesh, uint32_t f, const Point2& q) {
  int best = 0;
  double best_distance = -1;
  for (int i = 0; i < 3; ++i) {
    const double d = SquaredDistance(mesh.CornerPoint(f, i), q);
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
  // coordinates exist.
  if (!SibsonCoordinates(mesh, f, q, &neighbors)) {
    return LinearValue(mesh, f, q);
  }
  double value = 0;
  for (const NaturalNeighbor& n : neighbors) {
    value += n.weight * mesh.arrays().values[n.vertex];
  }
  return value;
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
