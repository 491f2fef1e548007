// Terrain tiles of a TIN in UTM zone 33N: every pixel of a tile over the
// data decodes to the value LocateBatch gives at the pixel's centre
// (transformed exactly from EPSG:3857 by a CrsTransformer of the test's
// own) within half the encoding's quantum (a quantum and a half on an
// edge), plus the facet's slope times the distance from the renderer's
// approximate centre, which is within kTilePositionTolerance of the exact
// one; on facets of slope <= 1 that shift moves no value by half a quantum.
// It is transparent exactly where LocateBatch finds no value, and a tile
// wholly over the data is an RGB PNG. Tiles far away or of the whole world
// are transparent where PROJ cannot go, a dataset without a CRS or values
// gets none, and TileJSON names the right zooms.

#include "server/tiles/terrain_tile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "tests/server/tiles/png_decode.h"
#include "tests/server/tiles/tile_test_support.h"

namespace locator {
namespace {

using test::kSide;
using test::kSouth;
using test::kUtm33;
using test::kWest;
using test::MercatorUtmTransformer;
using test::PixelCentresInUtm33;
using test::Slope;
using test::TileAtSouthWestCorner;
using test::TileContaining;
using test::UtmTerrain;

using ::testing::HasSubstr;

class TerrainTileTest : public ::testing::TestWithParam<TerrainEncoding> {
 protected:
  static void SetUpTestSuite() {
    engine_ = UtmTerrain(20000, kUtm33).release();
  }
  static void TearDownTestSuite() { delete engine_; }
  static Engine* engine_;
};
Engine* TerrainTileTest::engine_ = nullptr;

TEST_P(TerrainTileTest, PixelsAreLocateBatchValuesAtTheirCentres) {
  const TerrainEncoding encoding = GetParam();
  const double q = TerrainQuantum(encoding);
  // Two tiles partly over the data, so that both kinds of pixel are
  // checked, and one wholly over it, written without an alpha channel.
  const std::array<std::pair<TileAddress, bool>, 3> tiles = {
      {{TileAtSouthWestCorner(13), false},
       {TileAtSouthWestCorner(15), false},
       {TileContaining(16, Point2{kWest + kSide / 2, kSouth + kSide / 2}),
        true}}};
  for (const auto& [tile, wholly_over_data] : tiles) {
    const uint32_t z = tile.z;
    const StatusOr<std::string> png =
        RenderTerrainTile(*engine_, "utm", tile, encoding);
    ASSERT_TRUE(png.ok()) << png.status().ToString();
    test::RgbaImage image;
    ASSERT_TRUE(test::DecodeRgbaPng(*png, &image).ok());
    ASSERT_EQ(image.width, 256u);
    ASSERT_EQ(image.height, 256u);

    // The renderer's centres are approximate (kTilePositionTolerance): each
    // lies within the bound of its exact transform, in pixels of its row.
    const std::vector<Point2> centres = PixelCentresInUtm33(tile);
    std::vector<Point2> rendered;
    ASSERT_TRUE(TilePixelsInDatasetCrs(*engine_, tile, &rendered).ok());
    ASSERT_EQ(rendered.size(), centres.size());
    double worst_position = 0;  // in pixels
    for (size_t i = 0; i < centres.size(); ++i) {
      const Point2& first = centres[i / 256 * 256];
      const Point2& last = centres[i / 256 * 256 + 255];
      const double pixel = std::hypot(last.x - first.x, last.y - first.y) / 255;
      worst_position = std::max(
          {worst_position, std::abs(rendered[i].x - centres[i].x) / pixel,
           std::abs(rendered[i].y - centres[i].y) / pixel});
    }
    EXPECT_LE(worst_position, kTilePositionTolerance) << "z " << z;

    std::vector<LocateResult> located, at_rendered;
    ASSERT_TRUE(engine_->LocateBatch(centres, &located).ok());
    ASSERT_TRUE(engine_->LocateBatch(rendered, &at_rendered).ok());
    size_t opaque = 0, shifted_on_gentle_facets = 0;
    for (size_t i = 0; i < centres.size(); ++i) {
      const LocateResult& r = located[i];
      // Exact: no exact centre of these tiles lies within the bound of the
      // hull, so the approximation moves none across it.
      ASSERT_EQ(image.Alpha(i), r.has_value ? 255 : 0)
          << "z " << z << " pixel " << i % 256 << "," << i / 256;
      if (!r.has_value) continue;
      ++opaque;
      const bool on_edge =
          r.type == LocationType::kEdge || r.type == LocationType::kVertex;
      // The renderer draws the TIN at its centre: half a quantum of
      // rounding (a quantum more on an edge).
      ASSERT_TRUE(at_rendered[i].has_value);
      const double decoded = DecodeHeight(encoding, image.Rgb(i));
      ASSERT_NEAR(decoded, at_rendered[i].value,
                  (on_edge ? 1.5 : 0.5) * q + 1e-9)
          << "z " << z << " pixel " << i % 256 << "," << i / 256;
      // Against the exact centre, plus what the centre's shift costs: the
      // steeper facet's slope times the shift. The hull's sliver facets of
      // a random TIN are steep (slopes past 10), gentle ones move less than
      // half a quantum.
      const double slope = std::max(Slope(r), Slope(at_rendered[i]));
      const double shift = std::hypot(rendered[i].x - centres[i].x,
                                      rendered[i].y - centres[i].y);
      ASSERT_NEAR(decoded, r.value,
                  (on_edge ? 1.5 : 0.5) * q + slope * shift + 1e-9)
          << "z " << z << " pixel " << i % 256 << "," << i / 256;
      shifted_on_gentle_facets +=
          slope <= 1 && std::abs(at_rendered[i].value - r.value) >= 0.5 * q;
    }
    EXPECT_EQ(shifted_on_gentle_facets, 0u) << "z " << z;
    // The PNG's colour type (IHDR, byte 25): RGB (2) when no pixel is
    // transparent, else RGBA (6).
    ASSERT_GT(png->size(), 25u);
    EXPECT_EQ(static_cast<uint8_t>((*png)[25]), wholly_over_data ? 2 : 6)
        << "z " << z;
    if (wholly_over_data) {
      EXPECT_EQ(opaque, centres.size()) << "z " << z;
    } else {
      EXPECT_GT(opaque, 1000u) << "z " << z;
      EXPECT_LT(opaque, centres.size()) << "z " << z;
    }
  }
}

TEST_P(TerrainTileTest, TilesWithoutDataAreTransparent) {
  // The whole world (mostly outside the zone's area of use) and a tile in
  // the Pacific.
  for (const TileAddress& tile :
       {TileAddress{0, 0, 0}, TileAddress{6, 2, 30}}) {
    const StatusOr<std::string> png =
        RenderTerrainTile(*engine_, "utm", tile, GetParam());
    ASSERT_TRUE(png.ok()) << png.status().ToString();
    test::RgbaImage image;
    ASSERT_TRUE(test::DecodeRgbaPng(*png, &image).ok());
    size_t opaque = 0;
    for (size_t i = 0; i < 256 * 256; ++i) opaque += image.Alpha(i) != 0;
    // The 3 km of data fall within one pixel of the world or none.
    EXPECT_LE(opaque, 1u) << tile.z;
  }
}

INSTANTIATE_TEST_SUITE_P(Encodings, TerrainTileTest,
                         ::testing::Values(TerrainEncoding::kTerrarium,
                                           TerrainEncoding::kMapbox));

TEST(TerrainTileSourceTest, OnlyTilesWithinTheZoneSkipThePixelCheck) {
  const std::unique_ptr<gis::CrsTransformer> to_utm = MercatorUtmTransformer();
  EXPECT_TRUE(to_utm->SeparableBoxInAreaOfUse(TileAtSouthWestCorner(13).Box()));
  // UTM 33N is used from 12°E to 18°E, north of the equator.
  EXPECT_FALSE(to_utm->SeparableBoxInAreaOfUse(TileAddress{0, 0, 0}.Box()));
  EXPECT_FALSE(to_utm->SeparableBoxInAreaOfUse(TileAddress{3, 4, 2}.Box()));
}

TEST(TerrainTileSourceTest, ADatasetWithoutACrsGetsNoTiles) {
  const std::unique_ptr<Engine> engine = UtmTerrain(100, "");
  const StatusOr<std::string> png = RenderTerrainTile(
      *engine, "plain", TileAddress{0, 0, 0}, TerrainEncoding::kTerrarium);
  ASSERT_FALSE(png.ok());
  EXPECT_EQ(png.status().code(), Status::Code::kFailedPrecondition);
  EXPECT_THAT(png.status().message(),
              HasSubstr("dataset 'plain' has no CRS, so its terrain has no "
                        "place on a web map's tiles (EPSG:3857)"));
  EXPECT_EQ(
      TileJson(*engine, "plain", "u", TerrainEncoding::kMapbox).status().code(),
      Status::Code::kFailedPrecondition);
}

TEST(TerrainTileSourceTest, TileJsonBoundsAndZooms) {
  const std::unique_ptr<Engine> engine = UtmTerrain(20000, kUtm33);
  const StatusOr<std::string> json =
      TileJson(*engine, "utm", "http://h/t/{z}/{x}/{y}.png?encoding=mapbox",
               TerrainEncoding::kMapbox);
  ASSERT_TRUE(json.ok()) << json.status().ToString();
  EXPECT_THAT(*json, HasSubstr(R"("tilejson":"3.0.0")"));
  EXPECT_THAT(
      *json,
      HasSubstr(R"("tiles":["http://h/t/{z}/{x}/{y}.png?encoding=mapbox"])"));
  EXPECT_THAT(*json, HasSubstr(R"("encoding":"mapbox")"));
  // 3 km at 49.6°N is ~4.6 km of Mercator: one tile spans it from zoom 13
  // (4.9 km at the equator, 7.5 km of Mercator metres... per tile at 13 is
  // 4892 m), and 20000 points ~21 m apart in the field, ~33 Mercator metres,
  // want the zoom whose pixels are below that: 13 (19 m).
  EXPECT_THAT(*json, HasSubstr(R"("minzoom":13)"));
  EXPECT_THAT(*json, HasSubstr(R"("maxzoom":13)"));
  EXPECT_THAT(*json, HasSubstr(R"("bounds":[15.)"));
}

}  // namespace
}  // namespace locator
