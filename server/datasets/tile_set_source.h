// Tile sets as served datasets: `locatord --dataset big=DIR/manifest.json`
// serves the tile set locator-build wrote in DIR by mapping its assembled
// mesh file (server/core/tileset), never loading the points. A spec names
// a tile set when its file name is "manifest.json" or it starts with
// "tileset:" (tileset:PATH, for a manifest by another name).
//
// Thread-safety: free functions.

#ifndef LOCATOR_SERVER_DATASETS_TILE_SET_SOURCE_H_
#define LOCATOR_SERVER_DATASETS_TILE_SET_SOURCE_H_

#include <string>
#include <string_view>

#include "locator/status.h"
#include "server/core/tileset/tileset_manifest.h"

namespace locator {

// Whether `spec` names a tile set (see above).
bool IsTileSetSpec(std::string_view spec);

// Reads the manifest `spec` names into *manifest and its directory into
// *dir. NotFound if there is no such file; InvalidArgument naming the file
// if it is not a tile-set manifest.
[[nodiscard]] Status ReadTileSetSpec(std::string_view spec,
                                     TileSetManifestSummary* manifest,
                                     std::string* dir);

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASETS_TILE_SET_SOURCE_H_
