// MatchOpenEdges: the step both tile assemblies share (the serving mesh in
// memory, mesh_assembly.h; the tile set's mesh file out of core,
// tileset/tileset_mesh.h). Each tile leaves open the edges of its owned
// triangles whose other side another tile owns, and its hull edges; the
// two sides of an interior edge are paired by their ends, and what stays
// unpaired is the hull, ordered as ServingMesh's ring.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_TILING_OPEN_EDGES_H_
#define LOCATOR_CORE_TILING_OPEN_EDGES_H_

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "locator/status.h"

namespace locator {

// Edge `edge` of triangle number `face`, from vertex `start` to `end` (the
// triangle on its left).
struct OpenEdge {
  uint32_t face;
  uint32_t edge;
  uint32_t start;
  uint32_t end;
};

// Pairs the two sides of every interior edge among `open` into *pairs and
// orders the rest, the hull, into *ring: from the edge ending at the vertex
// with the smallest public id (`id_of`), each edge ending where the one
// before it starts. The result depends on the edges only, not on their
// order. Internal, prefixed with `what`, if an edge borders more than two
// triangles, its two triangles overlap, the hull is not one closed ring, or
// `id_of` fails (its error).
[[nodiscard]] Status MatchOpenEdges(
    std::string_view what, std::vector<OpenEdge> open,
    const std::function<Status(uint32_t vertex, uint32_t* id)>& id_of,
    std::vector<std::array<OpenEdge, 2>>* pairs, std::vector<OpenEdge>* ring);

// Internal, prefixed with `what`, unless `vertices`, `triangles` and
// `hull_edges` satisfy Euler's formula for a triangulated point set
// (2V = F + H + 2).
[[nodiscard]] Status CheckEulerFormula(std::string_view what, size_t vertices,
                                       size_t triangles, size_t hull_edges);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_OPEN_EDGES_H_
