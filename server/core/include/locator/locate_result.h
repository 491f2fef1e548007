// The answer to one point-location query, in plain types.
//
// Invariants: for kFace/kEdge/kVertex, triangle_id is the stable id (0..F-1)
// of a finite triangle that contains the query point (closed), vertex_ids and
// vertices are that triangle's corners in counter-clockwise order, and
// barycentric sums to 1 (up to rounding). For kEdge the point lies on the edge
// opposite corner `feature_index`; for kVertex it coincides with corner
// `feature_index`. For kOutsideConvexHull, hull_edge_ids are the endpoints of
// the hull edge nearest to the query (seen from outside), and triangle_id,
// vertex_ids and vertices are the hull triangle on the inner side of that
// edge; barycentric and value are then not meaningful (has_value is false).
// For kOutsideDomain (inside the convex hull, but in a hole or outside the
// domain's boundary), domain_edge_ids are the endpoints of the nearest domain
// boundary edge; there is no triangle (triangle_id -1, vertex_ids -1), no
// barycentric (all 0) and no value.

#ifndef LOCATOR_LOCATE_RESULT_H_
#define LOCATOR_LOCATE_RESULT_H_

#include <array>
#include <cstdint>
#include <string_view>

#include "locator/geometry.h"

namespace locator {

enum class LocationType : uint8_t {
  kFace = 0,
  kEdge = 1,
  kVertex = 2,
  kOutsideConvexHull = 3,
  kOutsideDomain = 4,
};

std::string_view LocationTypeName(LocationType type);

// How much of a LocateResult a locate fills.
enum class Detail : uint8_t {
  kFull,      // everything
  kLocation,  // all but barycentric and value (zeros, has_value false)
  // All but the value: has_value says whether the point has one, and the
  // caller computes it (the engine, for an interpolation other than linear).
  kAllButValue,
};

// Cost of one query in the paper's metric: faces visited by the walk plus
// distance comparisons made to pick a start, plus one per O(1) table lookup.
struct LocateCost {
  uint32_t faces_visited = 0;
  uint32_t comparisons = 0;
  uint32_t table_lookups = 0;

  uint32_t total() const { return faces_visited + comparisons + table_lookups; }
};

struct LocateResult {
  LocationType type = LocationType::kFace;
  int64_t triangle_id = -1;
  std::array<int64_t, 3> vertex_ids = {-1, -1, -1};
  std::array<Point2, 3> vertices = {};
  std::array<double, 3> barycentric = {0, 0, 0};
  // Index (0..2) of the edge (opposite that corner) for kEdge, or of the
  // corner for kVertex; -1 otherwise.
  int8_t feature_index = -1;
  bool has_value = false;
  double value = 0;  // interpolated z, valid when has_value
  std::array<int64_t, 2> hull_edge_ids = {-1, -1};
  // Endpoints of the nearest domain boundary edge, for kOutsideDomain.
  std::array<int64_t, 2> domain_edge_ids = {-1, -1};
  LocateCost cost;
};

}  // namespace locator

#endif  // LOCATOR_LOCATE_RESULT_H_
