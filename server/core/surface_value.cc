#include "server/core/surface_value.h"

#include <array>
#include <string>
#include <vector>

#include "server/core/barycentric.h"
#include "server/core/natural_neighbor.h"

namespace locator {
namespace {

double LinearValue(Triangulation::Face_handle f, const Point2& q) {
  std::array<Point2, 3> corners;
  for (int i = 0; i < 3; ++i) {
    corners[i] = Triangulation::FromCgal(f->vertex(i)->point());
  }
  const std::array<double, 3> b =
      Barycentric(corners[0], corners[1], corners[2], q);
  double value = 0;
  for (int i = 0; i < 3; ++i) value += b[i] * f->vertex(i)->info().value;
  return value;
}

double NearestValue(Triangulation::Face_handle f, const Point2& q) {
  int best = 0;
  double best_distance = -1;
  for (int i = 0; i < 3; ++i) {
    const double d =
        SquaredDistance(Triangulation::FromCgal(f->vertex(i)->point()), q);
    const bool nearer = best_distance < 0 || d < best_distance ||
                        (d == best_distance &&
                         f->vertex(i)->info().id < f->vertex(best)->info().id);
    if (nearer) {
      best = i;
      best_distance = d;
    }
  }
  return f->vertex(best)->info().value;
}

double NaturalNeighborValue(const Triangulation& t,
                            Triangulation::Face_handle f, const Point2& q) {
  thread_local std::vector<NaturalNeighbor> neighbors;
  // q is in the closed triangle f, so inside the closed hull: Sibson's
  // coordinates exist.
  if (!SibsonCoordinates(t, f, q, &neighbors)) return LinearValue(f, q);
  double value = 0;
  for (const NaturalNeighbor& n : neighbors) {
    value += n.weight * n.vertex->info().value;
  }
  return value;
}

}  // namespace

Status CheckInterpolation(const Triangulation& t, Interpolation how) {
  if (how == Interpolation::kNaturalNeighbor && t.num_constraints() > 0) {
    return Status::InvalidArgument(
        "natural-neighbor interpolation needs a Delaunay triangulation, and "
        "this dataset has " +
        std::to_string(t.num_constraints()) +
        " constrained segments (breaklines, a domain or a mesh); use linear "
        "or nearest");
  }
  return Status::OK();
}

double ValueAt(const Triangulation& t, Triangulation::Face_handle f,
               const Point2& q, Interpolation how) {
  switch (how) {
    case Interpolation::kNaturalNeighbor:
      return NaturalNeighborValue(t, f, q);
    case Interpolation::kNearest:
      return NearestValue(f, q);
    case Interpolation::kLinear:
      break;
  }
  return LinearValue(f, q);
}

}  // namespace locator
