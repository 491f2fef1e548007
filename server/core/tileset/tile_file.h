// Tile files: one tile of a tile set (tileset_build.h) as the build wrote
// it: the tile's own vertices (points, public ids, values) and the
// triangles it owns (TileTriangles: corners as global vertex indices,
// neighbours as indices among its own triangles or kOpen).
//
// Layout (little-endian, native doubles; sections start at multiples of 64
// bytes): a 128-byte header (magic "loctile\0", version, the tile set's
// build key, the tile's number, cell and vertex ranges and counts, an
// XXH3-64 checksum of the sections and one of the header's other bytes),
// then points (16 B each), ids (4 B), values (8 B; none without values) and
// triangles (24 B).
//
// Thread-safety: free functions.

#ifndef LOCATOR_CORE_TILESET_TILE_FILE_H_
#define LOCATOR_CORE_TILESET_TILE_FILE_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "locator/geometry.h"
#include "locator/status.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tiling/tile_triangulation.h"

namespace locator {

inline constexpr uint32_t kTileFileVersion = 1;
inline constexpr size_t kTileFileHeaderBytes = 128;

// What a tile file says of its tile besides its arrays.
struct TileFileInfo {
  uint64_t build_key = 0;
  uint32_t number = 0;
  Tile tile;
  uint64_t triangles = 0;
  uint64_t halo_points = 0;
  uint32_t rounds = 0;
  bool has_values = false;
  uint64_t file_bytes = 0;
  uint64_t checksum = 0;  // of the sections
};

// The arrays of a tile file, viewing the bytes they were decoded from.
struct TileFileArrays {
  std::span<const Point2> points;
  std::span<const uint32_t> ids;
  std::span<const double> values;
  std::span<const MeshTriangle> triangles;
};

// Writes the tile `info` describes, with its own vertices' `points`, `ids`
// and `values` (empty without values) and its `triangles`, to `path`
// atomically; fills info->file_bytes and info->checksum. IOError naming
// the step that failed.
[[nodiscard]] Status WriteTileFile(const std::string& path,
                                   std::span<const Point2> points,
                                   std::span<const uint32_t> ids,
                                   std::span<const double> values,
                                   std::span<const MeshTriangle> triangles,
                                   TileFileInfo* info);

// Reads the header of the tile file at `path` and checks it (magic,
// version, header checksum, length). NotFound if there is no file;
// InvalidArgument naming the check that failed.
[[nodiscard]] Status ReadTileFileInfo(const std::string& path,
                                      TileFileInfo* info);

// Checks a whole tile file's `bytes` (the header as above, then the
// sections' checksum) and points *arrays into them. InvalidArgument naming
// the first check that failed.
[[nodiscard]] Status DecodeTileFile(std::string_view bytes, TileFileInfo* info,
                                    TileFileArrays* arrays);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_TILE_FILE_H_
