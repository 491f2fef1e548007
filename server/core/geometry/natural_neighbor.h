// Sibson's natural-neighbour coordinates over the serving mesh, computed
// the way CGAL's natural_neighbor_coordinates_2 does (the Bowyer-Watson
// conflict zone of q, and the area each neighbour's Voronoi cell would lose
// to q), with CGAL's exact in-circle predicate (circle.h). The mesh of a
// dataset without constraints is its Delaunay triangulation, which is what
// Sibson's coordinates need; callers check that (CheckInterpolation).
//
// Thread-safety: reads the immutable mesh only; no face marks, so any
// number of threads may call it at once.

#ifndef LOCATOR_CORE_NATURAL_NEIGHBOR_H_
#define LOCATOR_CORE_NATURAL_NEIGHBOR_H_

#include <cstdint>
#include <vector>

#include "locator/geometry.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

struct NaturalNeighbor {
  // Mesh vertex index (its value is mesh.arrays().values[vertex]).
  uint32_t vertex = 0;
  // Sibson's coordinate: > 0, and the weights of one call sum to 1.
  double weight = 0;
};

// Sibson's coordinates of q into `out` (cleared first). `f` is a face whose
// closed triangle contains q. Preconditions: the mesh has no constrained
// edges (it is Delaunay), q is finite. Returns false, with `out` empty, when q
// is outside the closed convex hull (or, never seen, on the line of an edge
// of its conflict zone's boundary). On a vertex: that vertex with weight 1.
// On a hull edge: its two endpoints, weighted linearly along the edge (the
// limit of Sibson's coordinates there). The areas are computed in long
// double in a frame scaled to the conflict zone, so the weights are finite
// and right at every scale of the dataset, and again exactly where needles
// near q make the long double ones doubtful.
bool SibsonCoordinates(const ServingMesh& mesh, uint32_t f, const Point2& q,
                       std::vector<NaturalNeighbor>* out);

}  // namespace locator

#endif  // LOCATOR_CORE_NATURAL_NEIGHBOR_H_
