// The XYZ tile scheme and the terrain encodings: tile boxes tile the Web
// Mercator square, every hostile path segment is refused naming its range,
// and each encoding round-trips a height within half its quantum.

#include "server/tiles/tile_address.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "server/tiles/terrain_encoding.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

TEST(TileAddressTest, BoxesTileTheMercatorSquare) {
  const double h = TileAddress::kHalfWorld;
  const BoundingBox world = TileAddress{0, 0, 0}.Box();
  EXPECT_EQ(world.min_x, -h);
  EXPECT_EQ(world.max_x, h);
  EXPECT_EQ(world.min_y, -h);
  EXPECT_EQ(world.max_y, h);
  // y grows south: tile (1, 1, 0) is the north-east quarter.
  const BoundingBox ne = TileAddress{1, 1, 0}.Box();
  EXPECT_EQ(ne.min_x, 0);
  EXPECT_EQ(ne.min_y, 0);
  EXPECT_EQ(ne.max_x, h);
  EXPECT_EQ(ne.max_y, h);
  const RasterSpec raster = TileAddress{1, 1, 0}.Raster();
  EXPECT_EQ(raster.width, 256u);
  const Point2 first = raster.CellCentre(0, 0);
  EXPECT_DOUBLE_EQ(first.x, h / 512);
  EXPECT_DOUBLE_EQ(first.y, h - h / 512);
}

TEST(TileAddressTest, ParsesTheDeepestTiles) {
  const StatusOr<TileAddress> last =
      ParseTileAddress("24", "16777215", "16777215");
  ASSERT_TRUE(last.ok()) << last.status().ToString();
  EXPECT_EQ(last->z, 24u);
  EXPECT_EQ(last->x, 16777215u);
  EXPECT_EQ(last->y, 16777215u);
}

TEST(TileAddressTest, RefusesEverySegmentOutOfRange) {
  struct Row {
    const char *z, *x, *y, *message;
  };
  const Row rows[] = {
      {"25", "0", "0", "tile zoom '25' is not a whole number in 0..24"},
      {"-1", "0", "0", "tile zoom '-1'"},
      {"+1", "0", "0", "tile zoom '+1'"},
      {"", "0", "0", "tile zoom ''"},
      {"1e1", "0", "0", "tile zoom '1e1'"},
      {"99999999999999999999", "0", "0", "tile zoom"},
      {"1", "2", "0", "tile x at zoom 1 '2' is not a whole number in 0..1"},
      {"1", "0", "2", "tile y at zoom 1 '2' is not a whole number in 0..1"},
      {"3", "0x1", "0", "tile x at zoom 3 '0x1'"},
      {"3", "1 ", "0", "tile x at zoom 3 '1 '"},
      {"24", "16777216", "0", "in 0..16777215"},
      {"24", "0", "4294967297", "tile y at zoom 24"},
      {"0", "0", "%00", "tile y at zoom 0"},
  };
  for (const Row& row : rows) {
    const StatusOr<TileAddress> parsed = ParseTileAddress(row.z, row.x, row.y);
    ASSERT_FALSE(parsed.ok()) << row.z << "/" << row.x << "/" << row.y;
    EXPECT_EQ(parsed.status().code(), Status::Code::kInvalidArgument);
    EXPECT_THAT(parsed.status().message(), HasSubstr(row.message));
  }
}

TEST(TileAddressTest, ZoomForPixelSize) {
  const double zoom0 = 2 * TileAddress::kHalfWorld / 256;
  EXPECT_EQ(ZoomForPixelSize(zoom0 * 2, false), 0u);
  EXPECT_EQ(ZoomForPixelSize(zoom0 / 8, false), 3u);
  EXPECT_EQ(ZoomForPixelSize(zoom0 / 9, false), 3u);
  EXPECT_EQ(ZoomForPixelSize(zoom0 / 9, true), 4u);
  EXPECT_EQ(ZoomForPixelSize(1e-9, true), TileAddress::kMaxZoom);
  EXPECT_EQ(ZoomForPixelSize(std::nan(""), true), 0u);
}

TEST(TerrainEncodingTest, ParsesNamesAndRefusesOthers) {
  EXPECT_EQ(*ParseTerrainEncoding(""), TerrainEncoding::kTerrarium);
  EXPECT_EQ(*ParseTerrainEncoding("terrarium"), TerrainEncoding::kTerrarium);
  EXPECT_EQ(*ParseTerrainEncoding("mapbox"), TerrainEncoding::kMapbox);
  const StatusOr<TerrainEncoding> bad = ParseTerrainEncoding("Mapbox");
  ASSERT_FALSE(bad.ok());
  EXPECT_THAT(bad.status().message(),
              HasSubstr("unknown encoding 'Mapbox'; the encodings are "
                        "terrarium (the default) and mapbox"));
}

TEST(TerrainEncodingTest, TheDocumentedFormulas) {
  // Terrarium: R * 256 + G + B / 256 - 32768.
  EXPECT_EQ(DecodeHeight(TerrainEncoding::kTerrarium, {128, 0, 0}), 0);
  EXPECT_EQ(EncodeHeight(TerrainEncoding::kTerrarium, 1.5),
            (std::array<uint8_t, 3>{128, 1, 128}));
  // Mapbox: -10000 + (R * 65536 + G * 256 + B) * 0.1.
  EXPECT_EQ(EncodeHeight(TerrainEncoding::kMapbox, 0),
            (std::array<uint8_t, 3>{1, 134, 160}));
  EXPECT_NEAR(DecodeHeight(TerrainEncoding::kMapbox, {1, 134, 160}), 0, 1e-9);
}

TEST(TerrainEncodingTest, RoundTripsWithinHalfAQuantumAndClamps) {
  for (TerrainEncoding e :
       {TerrainEncoding::kTerrarium, TerrainEncoding::kMapbox}) {
    const double q = TerrainQuantum(e);
    for (double h : {-9999.97, -432.123, 0.0, 0.004, 8848.86, 12345.678}) {
      EXPECT_NEAR(DecodeHeight(e, EncodeHeight(e, h)), h, q / 2 + 1e-9)
          << TerrainEncodingName(e) << " " << h;
    }
    EXPECT_EQ(EncodeHeight(e, -1e300), (std::array<uint8_t, 3>{0, 0, 0}));
    EXPECT_EQ(EncodeHeight(e, 1e300), (std::array<uint8_t, 3>{255, 255, 255}));
  }
}

}  // namespace
}  // namespace locator
