// Interpolation: how the surface's value at a point is computed from the
// values at the triangulation's vertices.
//
// Linear interpolation is the piecewise-linear surface of the triangles
// (what LocateResult::value always held). Natural neighbour is Sibson's
// interpolation over the Delaunay triangulation: smooth, exact for linear
// functions, equal to the vertex value at a vertex; it needs a Delaunay
// triangulation, so a dataset with constraints (breaklines, a domain, a
// mesh) refuses it. Nearest is the value of the triangle's nearest corner.
//
// Thread-safety: pure functions over an immutable Triangulation.

#ifndef LOCATOR_CORE_INTERPOLATION_H_
#define LOCATOR_CORE_INTERPOLATION_H_

#include <cstdint>
#include <string_view>

#include "common/geometry.h"
#include "common/status.h"
#include "server/core/triangulation.h"

namespace locator {

enum class Interpolation : uint8_t {
  kLinear = 0,
  kNaturalNeighbor = 1,
  kNearest = 2,
};

// "linear", "natural-neighbor" or "nearest".
std::string_view InterpolationName(Interpolation how);

// OK if values can be interpolated `how` on t; InvalidArgument saying why
// not otherwise (natural neighbour on a triangulation with constraints).
[[nodiscard]] Status CheckInterpolation(const Triangulation& t,
                                        Interpolation how);

// The value at q, which lies in the closed triangle of the finite in-domain
// face f, interpolated `how`. Preconditions: t.has_values() and
// CheckInterpolation(t, how).ok().
double ValueAt(const Triangulation& t, Triangulation::Face_handle f,
               const Point2& q, Interpolation how);

}  // namespace locator

#endif  // LOCATOR_CORE_INTERPOLATION_H_
