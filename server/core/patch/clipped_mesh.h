// ClippedMesh and ClipMeshToBox: a TIN patch (MeshPatch) cut to an
// axis-parallel box, as a terrain tile needs it: every triangle of the patch
// clipped to the box (Sutherland-Hodgman), the pieces fanned into
// triangles, and the vertices on the box's sides marked.
//
// Two boxes that share a side compute the same vertices on it, bit for
// bit: a point where a TIN edge crosses the side is computed from the
// edge's ends in the order of their keys and from the side's coordinate
// alone, and a box corner's height from its TIN triangle in key order, so
// neither depends on which box asks. Neighbouring tiles clipped from the
// same TIN therefore meet without cracks.
//
// Thread-safety: pure functions over values.

#ifndef LOCATOR_CORE_PATCH_CLIPPED_MESH_H_
#define LOCATOR_CORE_PATCH_CLIPPED_MESH_H_

#include <array>
#include <cstdint>
#include <vector>

#include "locator/geometry.h"
#include "locator/mesh_patch.h"

namespace locator {

// The sides of a box a vertex lies on, as bits.
enum BoxSide : uint8_t {
  kWestSide = 1,
  kSouthSide = 2,
  kEastSide = 4,
  kNorthSide = 8,
};

// A triangulated surface within a box. Invariant: points, heights and
// sides have the same size, and edges that size or none; triangles are
// counter-clockwise index triples of non-zero area.
struct ClippedMesh {
  static constexpr uint32_t kNoEdge = 0xffffffffu;

  std::vector<Point2> points;
  std::vector<double> heights;
  std::vector<uint8_t> sides;  // BoxSide bits: which sides a point is on
  // For a point where an edge of the patch crosses a side, the edge's
  // ends (patch indices, in key order), so that the caller can put it on
  // the edge in a space where the patch is truly straight; {kNoEdge,
  // kNoEdge} for the others. ClipMeshToBox fills it.
  std::vector<std::array<uint32_t, 2>> edges;
  std::vector<std::array<uint32_t, 3>> triangles;

  size_t size() const { return points.size(); }
};

// The part of `patch` inside `box` (closed). Triangles with a corner that
// is not finite (a position PROJ could not map) or of zero area are left
// out; a triangle of the patch that is clockwise is turned around.
ClippedMesh ClipMeshToBox(const MeshPatch& patch, const BoundingBox& box);

}  // namespace locator

#endif  // LOCATOR_CORE_PATCH_CLIPPED_MESH_H_
