#include "server/tiles/quantized_mesh/geographic_tile.h"

#include <cmath>
#include <numbers>

#include "server/tiles/tile_address.h"

namespace locator {
namespace {

// Degrees per tile at `level`: 180 / 2^level, a power of two times 180, so
// that x * side is exact and both tiles on a side agree.
double Side(uint32_t level) {
  return std::ldexp(180.0, -static_cast<int>(level));
}

}  // namespace

BoundingBox GeographicTile::Box() const {
  const double side = Side(z);
  return BoundingBox{-180.0 + x * side, -90.0 + y * side,
                     -180.0 + (x + 1) * side, -90.0 + (y + 1) * side};
}

double LevelZeroGeometricError() {
  constexpr double kWgs84MaximumRadius = 6378137.0;
  constexpr int kHeightmapWidth = 65;
  constexpr int kTilesAtLevelZero = 2;
  return kWgs84MaximumRadius * 2 * std::numbers::pi * 0.25 /
         (kHeightmapWidth * kTilesAtLevelZero);
}

double GeometricError(uint32_t level) {
  return std::ldexp(LevelZeroGeometricError(), -static_cast<int>(level));
}

StatusOr<GeographicTile> ParseGeographicTile(std::string_view z,
                                             std::string_view x,
                                             std::string_view y) {
  StatusOr<TileAddress> parsed = ParseTilePath(
      z, x, y, GeographicTile::kMaxLevel, /*columns_at_zoom_0=*/2);
  if (!parsed.ok()) return parsed.status();
  return GeographicTile{.z = parsed->z, .x = parsed->x, .y = parsed->y};
}

}  // namespace locator
