// What the tile tests share besides the PNG reader: their terrain (a TIN of
// a known height function in UTM), the transformer between Web Mercator and
// the tests' UTM zone, and a tile's pixel centres computed from the XYZ
// scheme's definition (not from server/tiles), so that the tiles are
// checked against an independent account of where each pixel is.

#ifndef LOCATOR_TESTS_SERVER_TILES_TILE_TEST_SUPPORT_H_
#define LOCATOR_TESTS_SERVER_TILES_TILE_TEST_SUPPORT_H_

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "locator/engine.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/raster.h"
#include "server/tiles/tile_address.h"

namespace locator::test {

// The tests' data CRS: UTM zone 33N.
inline constexpr char kUtm33[] = "EPSG:32633";

// The terrain: a 3 km square of the zone, near 15°E 49.6°N.
inline constexpr double kWest = 500000, kSouth = 5500000, kSide = 3000;

// The terrain's height at p, in metres: hills and a gentle northward rise.
double Height(const Point2& p);

// An engine over `n` uniform points of the square with their Heights, in
// `crs` (none if empty); a test failure (and nullptr) if it fails.
std::unique_ptr<Engine> UtmTerrain(size_t n, const std::string& crs);

// The gradient of the plane through the points `v` at heights `h`:
// computed here, not by the engine.
FacetGradient PlaneGradient(const std::array<Point2, 3>& v,
                            const std::array<double, 3>& h);

// The gradient of the facet `r` found, its corners at their Heights.
FacetGradient Gradient(const LocateResult& r);

// The slope (|gradient|) of the facet `r` found.
double Slope(const LocateResult& r);

// The transformer between EPSG:3857 (its request side) and kUtm33; a test
// failure (and nullptr) if PROJ cannot make it.
std::unique_ptr<gis::CrsTransformer> MercatorUtmTransformer();

// The centres of `tile`'s 256x256 pixels, row by row from the north-west, in
// kUtm33; a test failure if one cannot be transformed.
std::vector<Point2> PixelCentresInUtm33(const TileAddress& tile);

// The tile of zoom `z` holding the point `utm` (in kUtm33).
TileAddress TileContaining(uint32_t z, const Point2& utm);

// The tile of zoom `z` holding the terrain's south-west corner, so that it
// is partly over the data.
TileAddress TileAtSouthWestCorner(uint32_t z);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_TILES_TILE_TEST_SUPPORT_H_
