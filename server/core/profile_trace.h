// TraceProfile: the straight-line walk that computes a Profile (see
// profile.h) over the triangulation.
//
// Thread-safety: a pure function over an immutable Triangulation.

#ifndef LOCATOR_CORE_PROFILE_TRACE_H_
#define LOCATOR_CORE_PROFILE_TRACE_H_

#include <span>

#include "common/geometry.h"
#include "common/status.h"
#include "server/core/profile.h"
#include "server/core/triangulation.h"

namespace locator {

// Traces `line` (at least 2 finite points; consecutive repeats allowed, as
// zero-length segments) over t into `out`. `start` is any finite face near
// line[0] (the walk to line[0] starts there). Values are set when
// t.has_values(): breakpoints and samples take ValueAt() with
// options.interpolation (the caller has checked CheckInterpolation).
// ResourceExhausted when the walk would enter more than options.max_faces
// faces; InvalidArgument for fewer than 2 points or a non-finite one.
[[nodiscard]] Status TraceProfile(const Triangulation& t,
                                  Triangulation::Face_handle start,
                                  std::span<const Point2> line,
                                  const ProfileOptions& options, Profile* out);

}  // namespace locator

#endif  // LOCATOR_CORE_PROFILE_TRACE_H_
