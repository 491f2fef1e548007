// WriteTileSetMesh: the serving mesh of a tile set, assembled out of core
// from its tile files into one mesh file (mesh_file.h) that locatord maps:
// the same file, byte for byte, that WriteMeshFile writes for the mesh
// BuildTiledMesh or Triangulation::Build make of the same points
// (AssembleServingMesh's rules: corners rotated to the smallest public id
// first, triangles ordered by centroid key then corner ids, neighbours
// across tiles matched by their ends, the hull ring from the edge ending at
// the hull vertex with the smallest public id).
//
// Out of core: the tiles' triangles go to bins by their centroid's cell
// (32 bytes each on disk), each bin is sorted in memory in turn, and the
// triangles are written in order with their neighbours renumbered through
// one 4-byte position per triangle (the one array held whole). Vertex data
// is read from the sorted points' files as needed.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_TILESET_TILESET_MESH_H_
#define LOCATOR_CORE_TILESET_TILESET_MESH_H_

#include <cstddef>
#include <string>

#include "locator/status.h"
#include "server/core/tileset/point_bins.h"
#include "server/core/tileset/tileset_manifest.h"

namespace locator {

struct TileSetMeshInput {
  const std::string& dir;   // the tile files
  const std::string& work;  // BinPoints' files
  const BinnedPoints& binned;
  const TileSetManifest& manifest;
  // The most triangles sorted in memory at once.
  size_t bin_triangles;
};

// Writes the mesh file of the tile set `in` describes to `path`
// (atomically). IOError naming the file that failed; Internal if the
// tiles' triangles do not fit together (a bug, never a wrong mesh).
[[nodiscard]] Status WriteTileSetMesh(const TileSetMeshInput& in,
                                      const std::string& path);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_TILESET_MESH_H_
