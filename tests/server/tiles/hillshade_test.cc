// Hillshade tiles of a TIN in UTM zone 33N. gdaldem hillshade, run on the
// raster the engine renders (what `locator grid` writes), shades every
// cell whose 3 x 3 window lies on one facet as the tile's shading of that
// facet does, within one grey level (gdaldem's reciprocal square root is
// approximate); a tile's pixels shade the facet under their centres (its
// gradient computed here from the corners), and are transparent exactly
// where the terrain has no facet. Bad options are refused by name.

#include "server/tiles/hillshade.h"

#include <gdal.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common/gis/raster_writer.h"
#include "locator/engine.h"
#include "server/tiles/terrain_tile.h"
#include "tests/server/tiles/png_decode.h"
#include "tests/server/tiles/tile_test_support.h"

namespace locator {
namespace {

using test::Gradient;
using test::kUtm33;
using test::TileAtSouthWestCorner;
using test::UtmTerrain;
using ::testing::HasSubstr;

TEST(HillshadeOptionsTest, DefaultsAreGdaldems) {
  const StatusOr<HillshadeOptions> options =
      ParseHillshadeOptions("", "", "", "");
  ASSERT_TRUE(options.ok());
  EXPECT_EQ(options->azimuth, 315);
  EXPECT_EQ(options->altitude, 45);
  EXPECT_EQ(options->z_factor, 1);
  EXPECT_EQ(options->scale, 1);
  EXPECT_EQ(HillshadeVariant(*options), "hillshade-315-45-1-1");
  const StatusOr<HillshadeOptions> set =
      ParseHillshadeOptions("0", "90", "2.5", "111120");
  ASSERT_TRUE(set.ok());
  EXPECT_EQ(HillshadeVariant(*set), "hillshade-0-90-2.5-111120");
}

TEST(HillshadeOptionsTest, OutOfRangeOrNotANumberIsRefusedByName) {
  struct Row {
    const char* azimuth;
    const char* altitude;
    const char* z_factor;
    const char* scale;
    const char* message;
  };
  for (const Row& row : std::vector<Row>{
           {"361", "", "", "", "azimuth '361' must be a number from 0 to 360"},
           {"-1", "", "", "", "azimuth '-1' must be a number from 0 to 360"},
           {"nan", "", "", "", "azimuth 'nan'"},
           {"1e300", "", "", "", "azimuth '1e300'"},
           {"north", "", "", "", "azimuth 'north'"},
           {"", "90.5", "", "",
            "altitude '90.5' must be a number from 0 to 90"},
           {"", "inf", "", "", "altitude 'inf'"},
           {"", "", "0", "", "z_factor '0' must be a number above 0 to 1e+09"},
           {"", "", "-2", "", "z_factor '-2'"},
           {"", "", "1e10", "", "z_factor '1e10'"},
           {"", "", "", "4.9e-324x", "scale '4.9e-324x'"},
           {"", "", "", "-inf", "scale '-inf'"},
       }) {
    const StatusOr<HillshadeOptions> options = ParseHillshadeOptions(
        row.azimuth, row.altitude, row.z_factor, row.scale);
    ASSERT_FALSE(options.ok()) << row.message;
    EXPECT_EQ(options.status().code(), Status::Code::kInvalidArgument);
    EXPECT_THAT(options.status().message(), HasSubstr(row.message));
  }
  // A denormal scale is positive and finite: taken.
  EXPECT_TRUE(ParseHillshadeOptions("", "", "", "4.9e-324").ok());
}

TEST(HillshadeShadeTest, FlatSteepAndFacingTheLight) {
  const HillshadeOptions light;  // from the north-west, 45° up
  // Flat: 1 + 254 sin 45°.
  EXPECT_EQ(Shade({0, 0}, light), 181);
  // Rising to the south-east at 45°: the facet faces the light squarely.
  const double s = std::sqrt(0.5);
  EXPECT_EQ(Shade({s, -s}, light), 255);
  // Rising to the north-west at more than 45°: turned away, darkest.
  EXPECT_EQ(Shade({-2, 2}, light), 1);
  // Vertical cliffs and overflowing slopes stay in range.
  EXPECT_EQ(Shade({1e300, 1e300}, light), 1);
  EXPECT_EQ(Shade({-INFINITY, 0}, light), 1);
  // No facet: no data.
  EXPECT_EQ(Shade({}, light), 0);
  // Exaggeration: twice the z factor on a north-west rise darkens it.
  HillshadeOptions doubled;
  doubled.z_factor = 2;
  EXPECT_LT(Shade({-0.2, 0.2}, doubled), Shade({-0.2, 0.2}, light));
  // scale divides as z_factor multiplies.
  doubled.scale = 2;
  EXPECT_EQ(Shade({-0.2, 0.2}, doubled), Shade({-0.2, 0.2}, light));
}

// Reads band 1 of `path` as doubles; a test failure if GDAL cannot.
std::vector<double> ReadBand(const std::string& path, int* width, int* height) {
  GDALAllRegister();
  GDALDatasetH dataset = GDALOpen(path.c_str(), GA_ReadOnly);
  EXPECT_NE(dataset, nullptr) << path;
  if (dataset == nullptr) return {};
  *width = GDALGetRasterXSize(dataset);
  *height = GDALGetRasterYSize(dataset);
  std::vector<double> cells(size_t(*width) * *height);
  EXPECT_EQ(
      GDALRasterIO(GDALGetRasterBand(dataset, 1), GF_Read, 0, 0, *width,
                   *height, cells.data(), *width, *height, GDT_Float64, 0, 0),
      CE_None);
  GDALClose(dataset);
  return cells;
}

TEST(HillshadeGdaldemTest, CellsOnOneFacetShadeAsGdaldemShadesThem) {
  // 2000 points on 3 km: facets ~70 m across, cells of 7.5 m, so that a
  // third of the 3 x 3 windows lie on one facet.
  const std::unique_ptr<Engine> engine = UtmTerrain(2000, kUtm33);
  ASSERT_NE(engine, nullptr);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("locator-hillshade-test-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string dem = (dir / "dem.tif").string();
  const std::string shaded = (dir / "shaded.tif").string();

  // The raster `locator grid` would write: the TIN at the cell centres.
  RasterSpec spec{.box = {test::kWest, test::kSouth, test::kWest + 3000,
                          test::kSouth + 3000},
                  .width = 400,
                  .height = 400,
                  .nodata = -9999};
  std::vector<double> cells(spec.cells());
  ASSERT_TRUE(engine->RenderRows(spec, 0, spec.height, cells.data()).ok());
  std::unique_ptr<gis::RasterWriter> writer;
  ASSERT_TRUE(gis::RasterWriter::Open(
                  dem,
                  gis::RasterShape{.width = spec.width,
                                   .height = spec.height,
                                   .box = spec.box,
                                   .cell_width = spec.cell_width(),
                                   .cell_height = spec.cell_height(),
                                   .nodata = spec.nodata,
                                   .crs_wkt = ""},
                  gis::RasterFormat{.driver = "GTiff"}, &writer)
                  .ok());
  ASSERT_TRUE(writer->WriteRows(0, spec.height, cells).ok());
  ASSERT_TRUE(writer->Close().ok());

  HillshadeOptions light;
  light.azimuth = 200;
  light.altitude = 30;
  light.z_factor = 3;
  light.scale = 1.5;
  const std::string command =
      "gdaldem hillshade -q -az 200 -alt 30 -z 3 -s 1.5 '" + dem + "' '" +
      shaded + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  int width = 0, height = 0;
  const std::vector<double> gdal = ReadBand(shaded, &width, &height);
  ASSERT_EQ(width, 400);
  ASSERT_EQ(height, 400);

  std::vector<Point2> centres;
  for (uint32_t row = 0; row < spec.height; ++row) {
    for (uint32_t col = 0; col < spec.width; ++col) {
      centres.push_back(spec.CellCentre(col, row));
    }
  }
  std::vector<LocateResult> located;
  ASSERT_TRUE(engine->LocateBatch(centres, &located).ok());
  std::vector<FacetGradient> gradients(centres.size());
  ASSERT_TRUE(
      engine->RenderGradients(centres, spec.width, gradients.data()).ok());
  size_t compared = 0, off_by_one = 0;
  for (int row = 1; row + 1 < height; ++row) {
    for (int col = 1; col + 1 < width; ++col) {
      const size_t i = size_t(row) * width + col;
      bool one_facet = true;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const LocateResult& r = located[i + dr * width + dc];
          one_facet = one_facet && r.type == LocationType::kFace &&
                      r.triangle_id == located[i].triangle_id;
        }
      }
      if (!one_facet) continue;
      ++compared;
      const int ours = Shade(gradients[i], light);
      ASSERT_NEAR(ours, gdal[i], 1) << "cell " << col << "," << row;
      off_by_one += ours != gdal[i];
      // And the engine's gradient is the facet's.
      const FacetGradient want = Gradient(located[i]);
      ASSERT_NEAR(gradients[i].dz_dx, want.dz_dx, 1e-9) << col << "," << row;
      ASSERT_NEAR(gradients[i].dz_dy, want.dz_dy, 1e-9) << col << "," << row;
    }
  }
  EXPECT_GT(compared, 400u * 400 / 4);
  // Rounding differences only, not a shifted light.
  EXPECT_LT(off_by_one, compared / 20) << off_by_one << " of " << compared;
  std::filesystem::remove_all(dir);
}

TEST(HillshadeTileTest, PixelsShadeTheFacetUnderTheirCentres) {
  const std::unique_ptr<Engine> engine = UtmTerrain(20000, kUtm33);
  ASSERT_NE(engine, nullptr);
  const HillshadeOptions light;
  for (uint32_t z : {13u, 16u}) {
    const TileAddress tile = TileAtSouthWestCorner(z);
    const StatusOr<std::string> png =
        RenderHillshadeTile(*engine, "utm", tile, light);
    ASSERT_TRUE(png.ok()) << png.status().ToString();
    test::RgbaImage image;
    ASSERT_TRUE(test::DecodeRgbaPng(*png, &image).ok());
    ASSERT_EQ(image.width, 256u);
    // Where the renderer puts each pixel (within kTilePositionTolerance of
    // its exact centre): the facet there is the one it shades.
    std::vector<Point2> rendered;
    ASSERT_TRUE(TilePixelsInDatasetCrs(*engine, tile, &rendered).ok());
    std::vector<LocateResult> located;
    ASSERT_TRUE(engine->LocateBatch(rendered, &located).ok());
    size_t shaded = 0, lit_differently = 0;
    for (size_t i = 0; i < located.size(); ++i) {
      const LocateResult& r = located[i];
      ASSERT_EQ(image.Alpha(i), r.has_value ? 255 : 0)
          << "z " << z << " pixel " << i % 256 << "," << i / 256;
      if (!r.has_value || r.type != LocationType::kFace) continue;
      ++shaded;
      const int want = Shade(Gradient(r), light);
      const int got = image.Rgb(i)[0];
      // The engine's gradient and this one round apart: a grey level.
      ASSERT_NEAR(got, want, 1) << "z " << z << " pixel " << i;
      lit_differently += got != want;
    }
    EXPECT_GT(shaded, 1000u) << "z " << z;
    EXPECT_LT(lit_differently, shaded / 100) << "z " << z;
  }
}

TEST(HillshadeTileTest, ADatasetWithoutACrsGetsNoTiles) {
  const std::unique_ptr<Engine> engine = UtmTerrain(100, "");
  ASSERT_NE(engine, nullptr);
  const StatusOr<std::string> png = RenderHillshadeTile(
      *engine, "plain", TileAddress{13, 4400, 2800}, HillshadeOptions());
  EXPECT_EQ(png.status().code(), Status::Code::kFailedPrecondition);
  EXPECT_THAT(png.status().message(), HasSubstr("has no CRS"));
}

}  // namespace
}  // namespace locator
