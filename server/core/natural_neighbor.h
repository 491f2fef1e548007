// Sibson's natural-neighbour coordinates over the triangulation, computed
// the way CGAL's natural_neighbor_coordinates_2 does (the Bowyer-Watson
// conflict zone of q, and the area each neighbour's Voronoi cell would lose
// to q), on the adapter's own type: CGAL's function needs a
// Delaunay_triangulation_2 (it calls dual()), and ours is a constrained
// Delaunay triangulation, which equals the Delaunay triangulation when it
// has no constraints. Callers check that (CheckInterpolation).
//
// Thread-safety: reads the immutable triangulation only; no face marks, so
// any number of threads may call it at once.

#ifndef LOCATOR_CORE_NATURAL_NEIGHBOR_H_
#define LOCATOR_CORE_NATURAL_NEIGHBOR_H_

#include <vector>

#include "common/geometry.h"
#include "server/core/triangulation.h"

namespace locator {

struct NaturalNeighbor {
  Triangulation::Vertex_handle vertex;
  // Sibson's coordinate: > 0, and the weights of one call sum to 1.
  double weight = 0;
};

// Sibson's coordinates of q into `out` (cleared first). `f` is a finite face
// whose closed triangle contains q. Preconditions: t has no constraints
// (it is Delaunay), q is finite. Returns false, with `out` empty, when q is
// outside the closed convex hull. On a vertex: that vertex with weight 1.
// On a hull edge: its two endpoints, weighted linearly along the edge (the
// limit of Sibson's coordinates there).
bool SibsonCoordinates(const Triangulation& t, Triangulation::Face_handle f,
                       const Point2& q, std::vector<NaturalNeighbor>* out);

}  // namespace locator

#endif  // LOCATOR_CORE_NATURAL_NEIGHBOR_H_
