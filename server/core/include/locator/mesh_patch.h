// MeshPatch: a piece of a TIN as plain arrays, for code that reshapes the
// surface outside the engine (a terrain tile clips it to its square and
// simplifies it): vertex positions, their heights and stable keys, and
// triangles as counter-clockwise index triples into them.
//
// Invariant: points, heights and keys have the same size, and every index
// of a triangle is below it.
//
// Thread-safety: a plain value.

#ifndef LOCATOR_MESH_PATCH_H_
#define LOCATOR_MESH_PATCH_H_

#include <array>
#include <cstdint>
#include <vector>

#include "locator/geometry.h"

namespace locator {

struct MeshPatch {
  std::vector<Point2> points;
  std::vector<double> heights;
  // A key per vertex that is the same wherever the vertex is cut out (the
  // TIN's public vertex id), so that two patches sharing an edge can order
  // its ends alike and compute the same points on it.
  std::vector<uint32_t> keys;
  std::vector<std::array<uint32_t, 3>> triangles;

  size_t size() const { return points.size(); }
};

}  // namespace locator

#endif  // LOCATOR_MESH_PATCH_H_
