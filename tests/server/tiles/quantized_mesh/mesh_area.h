// The area of a ClippedMesh, for the tests that check what it covers.

#ifndef LOCATOR_TESTS_SERVER_TILES_QUANTIZED_MESH_MESH_AREA_H_
#define LOCATOR_TESTS_SERVER_TILES_QUANTIZED_MESH_MESH_AREA_H_

#include <array>
#include <cstdint>

#include "server/core/patch/clipped_mesh.h"

namespace locator {

// Twice the signed area of triangle `t` of `m` (positive: counter-clockwise).
inline double TwiceArea(const ClippedMesh& m,
                        const std::array<uint32_t, 3>& t) {
  const Point2 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

// The sum of the areas of `m`'s triangles.
inline double Area(const ClippedMesh& m) {
  double area = 0;
  for (const auto& t : m.triangles) area += TwiceArea(m, t) / 2;
  return area;
}

}  // namespace locator

#endif  // LOCATOR_TESTS_SERVER_TILES_QUANTIZED_MESH_MESH_AREA_H_
