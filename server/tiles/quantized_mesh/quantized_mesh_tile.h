// Cesium terrain of a dataset: a GeographicTile of its TIN as
// quantized-mesh-1.0 (quantized_mesh_encoder.h), and the layer.json that
// tells CesiumJS's CesiumTerrainProvider where the tiles are.
//
// A tile is the TIN itself, not a resampling: the triangles over the tile
// (Engine::MeshInBox) with their vertices mapped to longitude and latitude
// by PROJ (the calling thread's CrsTransformer), clipped to the tile's box
// (ClipMeshToBox) and simplified within the level's geometric error
// (SimplifyClippedMesh with GeometricError(z)): at every vertex of the TIN
// inside the tile, and at every point where a TIN edge crosses the tile's
// sides, the tile's surface is within GeometricError(z) of the TIN, plus
// the encoding's quantization (half the height step, (max - min) / 32767,
// and the slope times half a u or v step). Between the TIN's vertices
// nothing is bounded: a simplified edge may cut under a ridge.
// Where the TIN has no data (outside its hull or domain, or the tile
// outside the data) the tile has no triangles: a hole, not a guess. Tiles
// sharing a side keep the same vertices on it, so the terrain is
// watertight.
//
// A dataset without a CRS or values gets no terrain (FAILED_PRECONDITION).
//
// Thread-safety: free functions over a thread-safe Engine; any thread.

#ifndef LOCATOR_SERVER_TILES_QUANTIZED_MESH_QUANTIZED_MESH_TILE_H_
#define LOCATOR_SERVER_TILES_QUANTIZED_MESH_QUANTIZED_MESH_TILE_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "locator/engine.h"
#include "locator/status_or.h"
#include "server/tiles/quantized_mesh/geographic_tile.h"

namespace locator {

// The CRS quantized-mesh tiles are in.
inline constexpr std::string_view kQuantizedMeshCrs = "EPSG:4326";

// The most TIN vertices one tile is cut from: a coarse tile over a large
// dataset fails with RESOURCE_EXHAUSTED beyond it, rather than take
// seconds and memory per request.
inline constexpr size_t kMaxTileSourceVertices = size_t{2} << 20;

// The quantized-mesh bytes of `tile` of dataset `name` served by `engine`.
// FAILED_PRECONDITION without a CRS or values; RESOURCE_EXHAUSTED past
// kMaxTileSourceVertices; InvalidArgument if PROJ cannot map the dataset's
// vertices to longitude and latitude.
StatusOr<std::string> RenderQuantizedMesh(const Engine& engine,
                                          std::string_view name,
                                          const GeographicTile& tile);

// The deepest level layer.json offers for `engine`'s dataset: the level
// whose tiles are 64 mean vertex spacings wide, where a tile holds the
// TIN's detail (beyond it Cesium refines the parent's mesh itself).
uint32_t DeepestQuantizedMeshLevel(const Engine& engine,
                                   const BoundingBox& lon_lat);

// The layer.json of dataset `name` (after CheckTileSource): tilejson
// 2.1.0, format quantized-mesh-1.0, the tms scheme, tiles
// "{z}/{x}/{y}.terrain?v={version}" with `version` (which changes with the
// data, so that caches see new URLs), EPSG:4326, the bounds, minzoom 0 and
// maxzoom DeepestQuantizedMeshLevel, `available`: per level the one range
// of tiles that meets the dataset's box, and no extensions.
StatusOr<std::string> LayerJson(const Engine& engine, std::string_view name,
                                std::string_view version);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_QUANTIZED_MESH_QUANTIZED_MESH_TILE_H_
