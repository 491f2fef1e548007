// Interpolation: how the surface's value at a point is computed from the
// values at the triangulation's vertices.
//
// Linear interpolation is the piecewise-linear surface of the triangles
// (what LocateResult::value always held). Natural neighbour is Sibson's
// interpolation over the Delaunay triangulation: smooth, exact for linear
// functions, equal to the vertex value at a vertex; it needs a Delaunay
// triangulation, so a dataset with constraints (breaklines, a domain, a
// mesh) refuses it. Nearest is the value of the triangle's nearest corner
// (ties to the smaller vertex id). See surface_value.h for the evaluation.

#ifndef LOCATOR_INTERPOLATION_H_
#define LOCATOR_INTERPOLATION_H_

#include <cstdint>
#include <string_view>

namespace locator {

enum class Interpolation : uint8_t {
  kLinear = 0,
  kNaturalNeighbor = 1,
  kNearest = 2,
};

// "linear", "natural-neighbor" or "nearest".
std::string_view InterpolationName(Interpolation how);

}  // namespace locator

#endif  // LOCATOR_INTERPOLATION_H_
