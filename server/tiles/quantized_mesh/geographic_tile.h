// GeographicTile: one tile of the geographic TMS scheme Cesium's terrain
// uses (EPSG:4326, "scheme": "tms" in layer.json): level z has 2^(z+1) x
// 2^z tiles, x growing east from 180°W and y growing north from 90°S, so
// level 0 is two tiles of 180° x 180°.
//
// Thread-safety: values and pure functions.

#ifndef LOCATOR_SERVER_TILES_QUANTIZED_MESH_GEOGRAPHIC_TILE_H_
#define LOCATOR_SERVER_TILES_QUANTIZED_MESH_GEOGRAPHIC_TILE_H_

#include <cstdint>
#include <string_view>

#include "locator/geometry.h"
#include "locator/status_or.h"

namespace locator {

struct GeographicTile {
  // The deepest level served: a tile 1.2 m wide at the equator, with a
  // geometric error of 5 mm.
  static constexpr uint32_t kMaxLevel = 24;

  uint32_t z = 0;
  uint32_t x = 0;
  uint32_t y = 0;

  // The tile's box in degrees (x longitude, y latitude). Tiles that share
  // a side compute it with the same arithmetic, bit for bit.
  BoundingBox Box() const;
};

// Cesium's estimate of the geometric error of level 0 in metres: the WGS84
// equator's quarter over a 65-sample heightmap across each of the two
// tiles (TerrainProvider.getEstimatedLevelZeroGeometricErrorForAHeightmap),
// 77067.34 m.
double LevelZeroGeometricError();

// Cesium's geometric error of `level`: LevelZeroGeometricError() / 2^level.
double GeometricError(uint32_t level);

// The tile of path segments `z`, `x` and `y` (decimal digits only).
// InvalidArgument naming the segment and its range: z in 0..kMaxLevel, x in
// 0..2^(z+1) - 1, y in 0..2^z - 1.
StatusOr<GeographicTile> ParseGeographicTile(std::string_view z,
                                             std::string_view x,
                                             std::string_view y);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_QUANTIZED_MESH_GEOGRAPHIC_TILE_H_
