// What the terrain tile tests share besides the PNG reader: the transformer
// between Web Mercator and the tests' UTM zone, and a tile's pixel centres
// computed from the XYZ scheme's definition (not from server/tiles), so that
// the tiles are checked against an independent account of where each pixel
// is.

#ifndef LOCATOR_TESTS_SERVER_TILES_TILE_TEST_SUPPORT_H_
#define LOCATOR_TESTS_SERVER_TILES_TILE_TEST_SUPPORT_H_

#include <memory>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "locator/geometry.h"
#include "server/tiles/tile_address.h"

namespace locator::test {

// The tests' data CRS: UTM zone 33N.
inline constexpr char kUtm33[] = "EPSG:32633";

// The transformer between EPSG:3857 (its request side) and kUtm33; a test
// failure (and nullptr) if PROJ cannot make it.
std::unique_ptr<gis::CrsTransformer> MercatorUtmTransformer();

// The centres of `tile`'s 256x256 pixels, row by row from the north-west, in
// kUtm33; a test failure if one cannot be transformed.
std::vector<Point2> PixelCentresInUtm33(const TileAddress& tile);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_TILES_TILE_TEST_SUPPORT_H_
