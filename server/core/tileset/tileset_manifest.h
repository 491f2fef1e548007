// The manifest of a tile set (manifest.json beside its tile files): what
// the set is built from, its bounds, fingerprints and statistics, and each
// tile's file, ranges, bounds and checksum. Every number a reader needs is
// there, so that a server can route by it without opening the tiles.
//
// Thread-safety: plain values and a pure function.

#ifndef LOCATOR_CORE_TILESET_TILESET_MANIFEST_H_
#define LOCATOR_CORE_TILESET_TILESET_MANIFEST_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"
#include "server/core/tileset/tile_file.h"

namespace locator {

inline constexpr uint32_t kTileSetManifestVersion = 1;

struct TileSetManifest {
  struct TileEntry {
    std::string file;  // relative to the manifest
    TileFileInfo info;
    BoundingBox bounds;  // of the tile's own vertices
  };
  std::string source;
  std::string crs;           // WKT; empty when the source has none
  uint64_t fingerprint = 0;  // DatasetFingerprint of the source
  uint64_t build_key = 0;
  uint64_t input_points = 0;
  uint64_t vertices = 0;
  bool has_values = false;
  BoundingBox bounds;
  int grid_level = 0;
  // The hull of all vertices, counter-clockwise, as global vertex indices.
  std::vector<uint32_t> hull;
  std::vector<TileEntry> tiles;
  // The assembled serving mesh (mesh_file.h), relative to the manifest.
  std::string mesh_file;
  double build_seconds = 0;
};

// The manifest as JSON text (keys in a fixed order, 64-bit digests as 16
// hex digits).
std::string ManifestJson(const TileSetManifest& manifest);

// What a server reads of a manifest to serve the tile set.
struct TileSetManifestSummary {
  std::string source;
  std::string crs;
  uint64_t fingerprint = 0;
  uint64_t input_points = 0;
  std::string mesh_file;  // relative to the manifest's directory
  // The tiles as routing sees them (common/routing/tile_router.h): the
  // grid's box and level, and the first cell of each tile, ascending.
  BoundingBox bounds;
  int grid_level = 0;
  std::vector<uint32_t> tile_first_cells;
};

// Reads the fields above from manifest text as ManifestJson writes it.
// InvalidArgument naming `name` and the first field that is missing or
// malformed (or the format or version that is not this one, or tiles whose
// cells do not follow each other from cell 0).
[[nodiscard]] Status ParseManifestSummary(std::string_view text,
                                          std::string_view name,
                                          TileSetManifestSummary* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_TILESET_MANIFEST_H_
