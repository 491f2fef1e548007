// SimplifyPoints: a point dataset with values thinned by greedy insertion
// (Garland and Heckbert, 1995) until every point lies within a stated
// vertical error of the TIN's linear surface.
//
// The domain is the input's own (its convex hull, or its rings and .poly
// segments and holes, as Triangulation::Build defines it). Kept: every
// corner of the convex hull, every constraint vertex (breaklines, rings,
// segments, and the vertices CGAL adds where constraints cross), and the
// points greedy insertion picks, one at a time, farthest from the surface
// first, keeping the triangulation constrained Delaunay. Kept points are
// exact; the error is measured at every dropped point. Repeated points are
// one vertex (the first one's value, as the engine merges them); the
// others count in the certificate at their own values.
//
// The certificate: stats->max_error is measured after the build at every
// served point with the engine's interpolation (Barycentric, or
// EdgeBarycentric on an edge; a vertex's own value), and any point found
// beyond max_error (a rounding difference from the build's measure) is
// inserted too. Points outside the domain (in a hole) are unserved. With
// max_error 0 only points exactly on the surface of the others are
// dropped. It runs on one thread (options.threads is not used).
//
// Output: `out` gets the kept points (in input order, then points of the
// constraints that are not dataset points) and their values, the input's
// crs and source, and the TIN as constraints.triangles (the in-domain
// triangles): the served mesh is exactly the surface the certificate
// measured.
// Breaklines and rings become mesh edges, so their segments are kept, but
// they are no longer reported as breaklines.
//
// Thread-safety: a free function; concurrent calls share nothing.

#ifndef LOCATOR_CORE_TERRAIN_SIMPLIFY_POINTS_H_
#define LOCATOR_CORE_TERRAIN_SIMPLIFY_POINTS_H_

#include "locator/dataset.h"
#include "locator/status.h"
#include "server/core/terrain/tin_options.h"

namespace locator {

// `in` thinned within options.max_error (see above) into *out, its
// certificate into *stats. InvalidArgument naming what is wrong: no values,
// a mesh given as triangles (it is served as given), any reason
// Triangulation::Build refuses `in`, max_points below the vertices the
// hull and the constraints need; or as CheckTinOptions.
Status SimplifyPoints(const Dataset& in, const TinOptions& options,
                      Dataset* out, SimplificationStats* stats);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_SIMPLIFY_POINTS_H_
