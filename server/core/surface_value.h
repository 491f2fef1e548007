// The surface's value at a point of a triangle, interpolated as asked (see
// interpolation.h): the one evaluation that Locate, LocateBatch, profiles
// and rasters share.
//
// Thread-safety: pure functions over an immutable Triangulation.

#ifndef LOCATOR_CORE_SURFACE_VALUE_H_
#define LOCATOR_CORE_SURFACE_VALUE_H_

#include "common/geometry.h"
#include "common/status.h"
#include "server/core/interpolation.h"
#include "server/core/triangulation.h"

namespace locator {

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

#endif  // LOCATOR_CORE_SURFACE_VALUE_H_
