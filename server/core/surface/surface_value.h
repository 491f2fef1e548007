// The surface's value at a point of a triangle, interpolated as asked (see
// interpolation.h): the one evaluation that Locate, LocateBatch, profiles
// and rasters share. It runs on the serving mesh.
//
// Thread-safety: pure functions over an immutable ServingMesh.

#ifndef LOCATOR_CORE_SURFACE_VALUE_H_
#define LOCATOR_CORE_SURFACE_VALUE_H_

#include <cstdint>

#include "locator/geometry.h"
#include "locator/interpolation.h"
#include "locator/status.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// OK if values can be interpolated `how` on a triangulation with
// `constraints` constrained segments; InvalidArgument saying why not
// otherwise (natural neighbour with constraints).
[[nodiscard]] Status CheckInterpolation(uint64_t constraints,
                                        Interpolation how);

// The value at q, which lies in the closed triangle of the in-domain face
// f, interpolated `how`. Preconditions: mesh.has_values() and
// CheckInterpolation(how) is OK for the mesh's dataset.
double ValueAt(const ServingMesh& mesh, uint32_t f, const Point2& q,
               Interpolation how);

}  // namespace locator

#endif  // LOCATOR_CORE_SURFACE_VALUE_H_
