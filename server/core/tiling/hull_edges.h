// HullEdges: the edges of the convex hull of a point set, every point on
// the hull's boundary a vertex (collinear ones included), as pairs of
// vertex indices: exactly the hull edges of its Delaunay triangulation.
// A tile certifies one of its own hull edges by finding it here.
//
// Thread-safety: immutable after Compute(); const methods from any thread.

#ifndef LOCATOR_CORE_TILING_HULL_EDGES_H_
#define LOCATOR_CORE_TILING_HULL_EDGES_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "locator/geometry.h"

namespace locator {

class HullEdges {
 public:
  // The hull of `points` (distinct, not all collinear), using exact
  // orientation tests on `threads` threads. Points strictly inside the
  // polygon of a few extreme points are dropped first, then Andrew's
  // monotone chain runs on the rest.
  static HullEdges Compute(std::span<const Point2> points, unsigned threads);

  // This hull with every point index i replaced by index[i]: the hull of a
  // point set computed from a subset that holds every point on its hull
  // (the out-of-core build's candidates), in the set's own numbering.
  // Precondition: index has an entry for every index of ring().
  HullEdges Renumbered(std::span<const uint32_t> index) const;

  // Whether a and b are consecutive points along the hull's boundary.
  bool Contains(uint32_t a, uint32_t b) const;
  // The hull's points in counter-clockwise order, each point on its
  // boundary once.
  const std::vector<uint32_t>& ring() const { return ring_; }

 private:
  // The hull whose points, counter-clockwise, are `ring`.
  static HullEdges FromRing(std::vector<uint32_t> ring);

  std::vector<uint32_t> ring_;
  // (min << 32 | max) of each edge's ends, sorted.
  std::vector<uint64_t> edges_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_HULL_EDGES_H_
