// TraceProfile: the straight-line walk that computes a Profile (see
// profile.h) over the serving mesh.
//
// Thread-safety: a pure function over an immutable ServingMesh.

#ifndef LOCATOR_CORE_PROFILE_TRACE_H_
#define LOCATOR_CORE_PROFILE_TRACE_H_

#include <cstdint>
#include <span>

#include "locator/geometry.h"
#include "locator/profile.h"
#include "locator/status.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// Traces `line` (at least 2 finite points; consecutive repeats allowed, as
// zero-length segments) over the mesh into `out`. `start` is any face near
// line[0] (the walk to line[0] starts there). Values are set when
// mesh.has_values(): breakpoints and samples take ValueAt() with
// options.interpolation (the caller has checked CheckInterpolation).
// ResourceExhausted when the walk would enter more than options.max_faces
// faces; InvalidArgument for fewer than 2 points, a non-finite one, or a
// line longer than the largest double (its distances would overflow).
// Every point, distance and value of the profile is finite.
[[nodiscard]] Status TraceProfile(const ServingMesh& mesh, uint32_t start,
                                  std::span<const Point2> line,
                                  const ProfileOptions& options, Profile* out);

}  // namespace locator

#endif  // LOCATOR_CORE_PROFILE_TRACE_H_
