// ReadElevationGrid on rasters made at test time: where samples sit (pixel
// centres, PixelIsPoint GeoTIFFs and ASCII grids by their own coordinates),
// values with scale and offset, nodata from the nodata value, NaN and a mask,
// the CRS, the files read, and a row per bad input.

#include "common/gis/raster_grid.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "common/gis/crs_info.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/common/gis/raster_fixtures.h"
#include "tests/core/scratch_dir.h"

namespace locator::gis {
namespace {

using ::testing::Contains;
using testing::DemFixture;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class RasterGridTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const {
    return dir_.path() + "/" + name;
  }
  std::string Write(const std::string& name, const DemFixture& dem) const {
    const std::string path = Path(name);
    testing::WriteDem(path, dem);
    return path;
  }
  static DemFixture Small() {
    DemFixture dem;
    dem.width = 3;
    dem.height = 2;
    dem.geotransform = {1000, 10, 0, 2000, 0, -5};
    dem.values = {1, 2, 3, 4, 5, 6};
    return dem;
  }
  void ExpectError(const std::string& spec, Status::Code code,
                   const std::string& message,
                   const DatasetLimits& limits = DatasetLimits()) const {
    ElevationGrid grid;
    const Status status = ReadElevationGrid(spec, limits, &grid);
    EXPECT_EQ(status.code(), code) << spec << ": " << status.ToString();
    EXPECT_THAT(status.message(), HasSubstr(message)) << spec;
  }

  test::ScratchDir dir_;
};

TEST_F(RasterGridTest, SamplesSitAtPixelCentresWithTheirValues) {
  DemFixture dem = Small();
  dem.crs = "EPSG:32633";
  const std::string path = Write("small.tif", dem);
  ElevationGrid grid;
  std::vector<std::string> files;
  ASSERT_TRUE(ReadElevationGrid(path, DatasetLimits(), &grid, &files).ok());
  EXPECT_EQ(grid.width, 3u);
  EXPECT_EQ(grid.height, 2u);
  EXPECT_EQ(grid.origin_x, 1005);
  EXPECT_EQ(grid.origin_y, 1997.5);
  EXPECT_EQ(grid.step_x, 10);
  EXPECT_EQ(grid.step_y, -5);
  EXPECT_EQ(grid.SampleAt(2, 1).x, 1025);
  EXPECT_EQ(grid.SampleAt(2, 1).y, 1992.5);
  EXPECT_THAT(grid.values, ::testing::ElementsAre(1, 2, 3, 4, 5, 6));
  EXPECT_EQ(grid.source, path);
  const StatusOr<CrsInfo> crs = DescribeCrs(grid.crs);
  ASSERT_TRUE(crs.ok()) << crs.status().ToString();
  EXPECT_EQ(crs->epsg_code, 32633);
  EXPECT_THAT(files, Contains(path));
}

TEST_F(RasterGridTest, APixelIsPointGeoTiffSamplesAtItsTiePoints) {
  DemFixture dem = Small();
  dem.area_or_point = "Point";
  const std::string path = Write("point.tif", dem);
  // The file's own tie point: pixel (0, 0) is sampled at (1005, 1997.5).
  const std::string listed = testing::RunTool(
      GDALINFO_PATH, {"--config", "GTIFF_POINT_GEO_IGNORE", "TRUE", path});
  EXPECT_THAT(listed, HasSubstr("Origin = (1005.000000000000000,"
                                "1997.500000000000000)"));
  ElevationGrid grid;
  ASSERT_TRUE(ReadElevationGrid(path, DatasetLimits(), &grid).ok());
  EXPECT_EQ(grid.origin_x, 1005);
  EXPECT_EQ(grid.origin_y, 1997.5);
}

TEST_F(RasterGridTest, AnAsciiGridByCellCentresSamplesAtThem) {
  const std::string path = Path("centres.asc");
  testing::WriteFile(path,
                     "ncols 3\nnrows 2\nxllcenter 100\nyllcenter 200\n"
                     "cellsize 10\nNODATA_value -9999\n1 2 3\n4 -9999 6\n");
  ElevationGrid grid;
  ASSERT_TRUE(ReadElevationGrid(path, DatasetLimits(), &grid).ok());
  // The lower-left cell's centre is (100, 200), as the file says.
  EXPECT_EQ(grid.SampleAt(0, 1).x, 100);
  EXPECT_EQ(grid.SampleAt(0, 1).y, 200);
  EXPECT_EQ(grid.SampleAt(2, 0).x, 120);
  EXPECT_EQ(grid.SampleAt(2, 0).y, 210);
  EXPECT_TRUE(std::isnan(grid.ValueAt(1, 1)));
  EXPECT_EQ(grid.ValueAt(2, 1), 6);
  EXPECT_EQ(grid.ValidSamples(), 5u);
}

TEST_F(RasterGridTest, AppliesScaleAndOffsetAndMarksNodata) {
  DemFixture dem = Small();
  dem.type = "Int16";
  dem.values = {10, -32768, 30, 40, 50, 60};
  dem.has_nodata = true;
  dem.nodata = -32768;
  dem.scale = 0.5;
  dem.offset = 100;
  ElevationGrid grid;
  ASSERT_TRUE(
      ReadElevationGrid(Write("scaled.tif", dem), DatasetLimits(), &grid).ok());
  EXPECT_EQ(grid.ValueAt(0, 0), 105);
  EXPECT_TRUE(std::isnan(grid.ValueAt(1, 0)));
  EXPECT_EQ(grid.ValueAt(2, 1), 130);
  EXPECT_EQ(grid.ValidSamples(), 5u);
}

TEST_F(RasterGridTest, NanPixelsAndAMaskBandAreNodata) {
  DemFixture dem = Small();
  dem.values[4] = NAN;
  dem.mask = {true, true, false, true, true, true};
  ElevationGrid grid;
  ASSERT_TRUE(
      ReadElevationGrid(Write("masked.tif", dem), DatasetLimits(), &grid).ok());
  EXPECT_TRUE(std::isnan(grid.ValueAt(2, 0)));  // masked
  EXPECT_TRUE(std::isnan(grid.ValueAt(1, 1)));  // NaN
  EXPECT_EQ(grid.ValidSamples(), 4u);
}

TEST_F(RasterGridTest, ReadsTheBandItIsAskedForAndAssignsACrs) {
  DemFixture dem = Small();
  dem.bands = 2;
  const std::string path = Write("two.tif", dem);
  ElevationGrid grid;
  ASSERT_TRUE(ReadElevationGrid(path + "?band=2&a_srs=EPSG:4326&driver=GTiff",
                                DatasetLimits(), &grid)
                  .ok());
  EXPECT_EQ(grid.ValueAt(0, 0), 1001);
  const StatusOr<CrsInfo> crs = DescribeCrs(grid.crs);
  ASSERT_TRUE(crs.ok()) << crs.status().ToString();
  EXPECT_EQ(crs->epsg_code, 4326);
}

TEST_F(RasterGridTest, ReadsARasterLargerThanOneStrip) {
  // 4200 x 700 Float32: ~23 MB of doubles, two strips and a bit.
  const DemFixture dem = testing::HillDem(4200, 700, 1);
  ElevationGrid grid;
  ASSERT_TRUE(
      ReadElevationGrid(Write("big.tif", dem), DatasetLimits(), &grid).ok());
  size_t wrong = 0;
  for (size_t i = 0; i < dem.values.size(); ++i) {
    wrong += grid.values[i] != static_cast<float>(dem.values[i]);
  }
  EXPECT_EQ(wrong, 0u);
}

// The bad-input rows: each a precise error that names the source.
TEST_F(RasterGridTest, BadRasterTable) {
  const std::string small = Write("small.tif", Small());
  ExpectError(Path("missing.tif"), Status::Code::kNotFound,
              Path("missing.tif") + ": no such file or directory");

  const std::string text = Path("words.tif");
  testing::WriteFile(text, "not a raster\n");
  ExpectError(text, Status::Code::kInvalidArgument,
              text + ": GDAL cannot open it as a raster");
  const std::string xyz = Path("points.asc");
  testing::WriteFile(xyz, "1 2 3\n4 5 6\n");
  ExpectError(xyz, Status::Code::kInvalidArgument,
              "x,y,z text is read when the file is named .xyz or .csv");

  ExpectError(small + "?band=2", Status::Code::kInvalidArgument,
              small + ": band 2 is out of range: it has 1 band");
  ExpectError(small + "?band=0", Status::Code::kInvalidArgument,
              "option 'band' must be an integer from 1");
  ExpectError(small + "?bands=1", Status::Code::kInvalidArgument,
              "unknown option 'bands' (known: band, a_srs, driver, max_error, "
              "max_points)");
  ExpectError(small + "?driver=AAIGrid", Status::Code::kInvalidArgument,
              small + ": GDAL cannot open it as a raster with driver AAIGrid");
  ExpectError(small + "?driver=NoSuch", Status::Code::kInvalidArgument,
              small + ": no GDAL driver 'NoSuch' (driver=)");
  ExpectError(small + "?a_srs=EPSG:999999", Status::Code::kInvalidArgument,
              small + ": a_srs: unknown CRS 'EPSG:999999'");

  DemFixture hole = Small();
  hole.has_nodata = true;
  hole.nodata = -1;
  hole.values.assign(6, -1);
  const std::string empty = Write("empty.tif", hole);
  ExpectError(empty, Status::Code::kInvalidArgument,
              empty + ": band 1 has no valid pixel (all nodata)");

  DemFixture rotated = Small();
  rotated.geotransform = {1000, 10, 0.5, 2000, 0.25, -5};
  const std::string turned = Write("rotated.tif", rotated);
  ExpectError(turned, Status::Code::kInvalidArgument,
              turned +
                  " has a rotated geotransform (row rotation 0.5, "
                  "column rotation 0.25); locator serves north-up grids");

  DemFixture complex = Small();
  complex.type = "CFloat32";
  const std::string imaginary = Write("complex.tif", complex);
  ExpectError(imaginary, Status::Code::kInvalidArgument,
              imaginary +
                  ": band 1 holds CFloat32 values; an elevation band "
                  "must be real");

  DemFixture infinite = Small();
  infinite.values[5] = -INFINITY;
  const std::string inf = Write("inf.tif", infinite);
  ExpectError(inf, Status::Code::kInvalidArgument,
              inf + ": band 1 pixel (2, 1) is -inf, which is no elevation");

  DemFixture huge = Small();
  huge.type = "Float64";
  huge.values[3] = 1e39;
  const std::string beyond = Write("huge.tif", huge);
  ExpectError(beyond, Status::Code::kInvalidArgument,
              beyond +
                  ": band 1 pixel (0, 1) is 1e+39 after scale and "
                  "offset, beyond a float's range");

  DatasetLimits five;
  five.max_points = 5;
  ExpectError(small, Status::Code::kResourceExhausted,
              small + ": 3 x 2 = 6 pixels, more than 5 points", five);
}

TEST(RasterDatasetSpecTest, RecognizesRasterExtensionsAndThePrefix) {
  EXPECT_TRUE(IsRasterDatasetSpec("dem.tif"));
  EXPECT_TRUE(IsRasterDatasetSpec("/data/DEM.TIFF?band=2"));
  EXPECT_TRUE(IsRasterDatasetSpec("mosaic.vrt?max_error=0.5"));
  EXPECT_TRUE(IsRasterDatasetSpec("N45E006.hgt"));
  EXPECT_TRUE(IsRasterDatasetSpec("grid.asc"));
  EXPECT_TRUE(IsRasterDatasetSpec("raster:/vsizip/dem.zip/dem.png"));
  EXPECT_FALSE(IsRasterDatasetSpec("points.csv"));
  EXPECT_FALSE(IsRasterDatasetSpec("survey.gpkg"));
  EXPECT_FALSE(IsRasterDatasetSpec("tif"));
  const SpecParts parts = SplitRasterDatasetSpec("raster:a.png?band=2");
  EXPECT_EQ(parts.prefix, "raster:");
  EXPECT_EQ(parts.source, "a.png");
  EXPECT_EQ(parts.options, "?band=2");
}

}  // namespace
}  // namespace locator::gis
