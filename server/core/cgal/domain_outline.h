// OutlineOf, OutlineOfMesh: the DomainOutline (locator/engine_info.h) of a
// triangulation or of a mesh given as triangles: what a map of a constrained
// dataset draws over it, the domain's boundary (outer boundaries and holes
// alike) and its breaklines, as plain segments.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_DOMAIN_OUTLINE_H_
#define LOCATOR_CORE_DOMAIN_OUTLINE_H_

#include <cstddef>

#include "locator/engine_info.h"

namespace locator {

class ServingMesh;
class Triangulation;

// The outline of `t`, each list at most `max_edges` long: all its edges if
// they fit, else every k-th in sorted order (k as small as keeps the count
// within `max_edges`); each segment runs from its lexicographically smaller
// end, and the lists are sorted, so equal triangulations give equal
// outlines. O(E log E) in the E edges of the outline, O(edges of t) else.
DomainOutline OutlineOf(const Triangulation& t, size_t max_edges);

// The outline of a mesh given as triangles, from its serving mesh: every
// edge between an in-domain triangle and an out-of-domain face or the
// outside of the hull, thinned as OutlineOf's (a mesh has no breaklines).
DomainOutline OutlineOfMesh(const ServingMesh& mesh, size_t max_edges);

}  // namespace locator

#endif  // LOCATOR_CORE_DOMAIN_OUTLINE_H_
