// Tiles and their triangulations with certified halos.
//
// A tile is a range of cells along the grid's Hilbert curve, so its own
// vertices are a range of global vertex indices. It owns the triangles
// whose smallest vertex index is its own: every triangle of the global
// triangulation has exactly one owner, whichever tiles exist.
//
// TriangulateTile triangulates the tile's own points plus a halo of
// neighbouring cells with CGAL (whose insertion gives the canonical
// Delaunay triangulation of what it was given, canonical_delaunay.h), then
// certifies the star of every own vertex: a finite triangle when its closed
// circumdisk meets only cells the tile has seen (HaloCells), a hull edge
// when it is an edge of the global hull (HullEdges). Where a triangle is
// not certified, the cells it needs join the halo and the stars are checked
// again; the window the halo may grow into doubles when a region reaches
// past it. At the end every own vertex's star is the same as in the global
// canonical triangulation of all points (it is certified, and it is a full
// fan or reaches the global hull on both sides), so the owned triangles
// are exactly the global triangles this tile owns.
//
// Thread-safety: TriangulateTile may run for different tiles at once, each
// with its own HaloCells; the context is shared and read-only.

#ifndef LOCATOR_CORE_TILING_TILE_TRIANGULATION_H_
#define LOCATOR_CORE_TILING_TILE_TRIANGULATION_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "locator/status.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tiling/cells/cell_grid.h"
#include "server/core/tiling/cells/cell_source.h"
#include "server/core/tiling/cells/halo_cells.h"
#include "server/core/tiling/hull_edges.h"

namespace locator {

struct Tile {
  uint32_t first_cell = 0;  // cells [first_cell, end_cell) along the curve
  uint32_t end_cell = 0;
  uint32_t first_vertex = 0;  // its own vertices [first_vertex, end_vertex)
  uint32_t end_vertex = 0;

  bool operator==(const Tile&) const = default;
};

// The cells of `grid`, cut along the curve into tiles of at least
// `tile_vertices` vertices each (the last may have fewer); no tile is empty.
std::vector<Tile> CutTiles(const CellGrid& grid, const CellSource& source,
                           size_t tile_vertices);

// What every tile's triangulation reads.
struct TileContext {
  const CellGrid& grid;
  const CellSource& source;
  const HullEdges& hull;
  size_t vertices;  // all vertices, of all tiles
};

struct TileTriangles {
  // neighbor[i] of a triangle whose neighbour across edge i is not owned
  // by this tile (or is the outside of the hull).
  static constexpr uint32_t kOpen = 0xffffffffu;

  // The owned triangles: corners counter-clockwise as global vertex
  // indices, neighbours as indices into this list or kOpen.
  LargeVector<MeshTriangle> triangles;
  size_t own_points = 0;
  // Points inserted from other tiles' cells.
  size_t halo_points = 0;
  // Rounds of certification (1 when the first halo sufficed).
  int rounds = 0;
};

// Triangulates `tile` as described above into *out. Internal if a hull
// edge of all the points is missing from context.hull, or an owned
// triangle stays uncertified (neither can happen but by a bug).
Status TriangulateTile(const TileContext& context, const Tile& tile,
                       HaloCells* halo, TileTriangles* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_TILE_TRIANGULATION_H_
