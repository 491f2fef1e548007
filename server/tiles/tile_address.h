// TileAddress: one tile of the XYZ ("slippy map") scheme on Web Mercator
// (EPSG:3857) that web maps request: zoom z has 2^z x 2^z tiles of
// TileAddress::kPixels x kPixels pixels, x growing east from 180°W and y
// growing south from 85.0511°N, the square the projection maps the world
// to.
//
// Thread-safety: values and pure functions.

#ifndef LOCATOR_SERVER_TILES_TILE_ADDRESS_H_
#define LOCATOR_SERVER_TILES_TILE_ADDRESS_H_

#include <cstdint>
#include <string_view>

#include "locator/geometry.h"
#include "locator/raster.h"
#include "locator/status_or.h"

namespace locator {

struct TileAddress {
  // The deepest zoom served: a pixel of 2.4 cm at the equator, finer than
  // any survey; MapLibre's sources stop at 24 too.
  static constexpr uint32_t kMaxZoom = 24;
  // Pixels per tile side.
  static constexpr uint32_t kPixels = 256;
  // Half the side of the Web Mercator square, in metres (pi * 6378137).
  static constexpr double kHalfWorld = 20037508.342789244;

  uint32_t z = 0;
  uint32_t x = 0;
  uint32_t y = 0;

  // The tile's square in EPSG:3857 metres.
  BoundingBox Box() const;
  // The tile as a raster: its pixels' centres are the cells' (row 0 north).
  RasterSpec Raster() const;
};

// The tile of path segments `z`, `x` and `y` (decimal digits only, as
// "/tiles/{z}/{x}/{y}.png" gives them without the extension).
// InvalidArgument naming the segment and the range it must be in: z in
// 0..kMaxZoom, x and y in 0..2^z - 1.
StatusOr<TileAddress> ParseTileAddress(std::string_view z, std::string_view x,
                                       std::string_view y);

// As ParseTileAddress, for a scheme of `max_zoom` levels with
// `columns_at_zoom_0` tiles across and 1 down at zoom 0 (Cesium's
// geographic scheme has 2): x in 0..columns_at_zoom_0 * 2^z - 1.
StatusOr<TileAddress> ParseTilePath(std::string_view z, std::string_view x,
                                    std::string_view y, uint32_t max_zoom,
                                    uint32_t columns_at_zoom_0);

// The zoom, in 0..kMaxZoom, whose pixels are `metres` wide (EPSG:3857
// units) rounded down (`round_up` false: pixels at least that wide) or up
// (pixels at most that wide); 0 for NaN.
uint32_t ZoomForPixelSize(double metres, bool round_up);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_TILE_ADDRESS_H_
