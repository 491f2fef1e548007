// RasterWriter: rasters written as GTiff and COG, reopened with GDAL's API
// (size, geotransform, CRS, nodata, tiling, every value) and opened by the
// real gdalinfo; and its errors.

#include "common/gis/raster_writer.h"

#include <gdal_priv.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/testing/run_binary.h"

namespace locator::gis {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr double kNodata = -9999;

// 2 x 2 tiles of 256, the last row and column of tiles partial.
RasterShape TestShape() {
  RasterShape shape;
  shape.width = 300;
  shape.height = 270;
  shape.cell_width = 10;
  shape.cell_height = 20;
  shape.box = {500000, 5500000 - 270 * 20.0, 500000 + 300 * 10.0, 5500000};
  shape.nodata = kNodata;
  return shape;
}

// The value of cell (col, row); every eleventh diagonal has none.
double CellValue(uint32_t col, uint32_t row) {
  if ((col + row) % 11 == 0) return kNodata;
  return row * 1000.0 + col + 0.125;
}

// Writes the test raster in chunks of 7 rows, last chunk first.
Status WriteTestRaster(RasterWriter& writer, const RasterShape& shape) {
  constexpr uint32_t kChunk = 7;
  std::vector<uint32_t> firsts;
  for (uint32_t row = 0; row < shape.height; row += kChunk) {
    firsts.insert(firsts.begin(), row);
  }
  for (uint32_t first : firsts) {
    const uint32_t rows = std::min(kChunk, shape.height - first);
    std::vector<double> values;
    for (uint32_t row = first; row < first + rows; ++row) {
      for (uint32_t col = 0; col < shape.width; ++col) {
        values.push_back(CellValue(col, row));
      }
    }
    if (Status status = writer.WriteRows(first, rows, values); !status.ok()) {
      return status;
    }
  }
  return Status::OK();
}

// Opens `path` with GDAL, read only.
GDALDatasetUniquePtr Reopen(const std::string& path) {
  return GDALDatasetUniquePtr(
      GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
}

class RasterWriterTest : public ::testing::Test {
 protected:
  std::string PathOf(const std::string& name) const {
    return dir_.path() + "/" + name;
  }

  // Writes the test raster to `name` in `format`; the writes must succeed.
  std::string Write(const std::string& name, const RasterFormat& format,
                    const RasterShape& shape = TestShape()) {
    const std::string path = PathOf(name);
    std::unique_ptr<RasterWriter> writer;
    Status status = RasterWriter::Open(path, shape, format, &writer);
    EXPECT_TRUE(status.ok()) << status.ToString();
    if (!status.ok()) return path;
    status = WriteTestRaster(*writer, shape);
    EXPECT_TRUE(status.ok()) << status.ToString();
    status = writer->Close();
    EXPECT_TRUE(status.ok()) << status.ToString();
    return path;
  }

  // Checks everything GDAL reads back from a file of the test raster.
  void ExpectTestRaster(const std::string& path, int block_size) {
    const GDALDatasetUniquePtr dataset = Reopen(path);
    ASSERT_NE(dataset, nullptr) << path;
    const RasterShape shape = TestShape();
    ASSERT_EQ(dataset->GetRasterXSize(), 300);
    ASSERT_EQ(dataset->GetRasterYSize(), 270);
    ASSERT_EQ(dataset->GetRasterCount(), 1);
    double transform[6];
    ASSERT_EQ(dataset->GetGeoTransform(transform), CE_None);
    EXPECT_THAT(transform, ElementsAre(500000, 10, 0, 5500000, 0, -20));
    const OGRSpatialReference* crs = dataset->GetSpatialRef();
    ASSERT_NE(crs, nullptr);
    EXPECT_STREQ(crs->GetAuthorityCode(nullptr), "32633");

    GDALRasterBand* band = dataset->GetRasterBand(1);
    EXPECT_EQ(band->GetRasterDataType(), GDT_Float64);
    int has_nodata = 0;
    EXPECT_EQ(band->GetNoDataValue(&has_nodata), kNodata);
    EXPECT_TRUE(has_nodata);
    int block_x = 0, block_y = 0;
    band->GetBlockSize(&block_x, &block_y);
    EXPECT_EQ(block_x, block_size);
    EXPECT_EQ(block_y, block_size);

    std::vector<double> values(size_t{shape.width} * shape.height);
    ASSERT_EQ(band->RasterIO(GF_Read, 0, 0, 300, 270, values.data(), 300, 270,
                             GDT_Float64, 0, 0, nullptr),
              CE_None);
    size_t wrong = 0;
    for (uint32_t row = 0; row < shape.height; ++row) {
      for (uint32_t col = 0; col < shape.width; ++col) {
        const double got = values[size_t{row} * shape.width + col];
        if (got != CellValue(col, row) && ++wrong <= 5) {
          ADD_FAILURE() << "cell (" << col << ", " << row << "): " << got
                        << ", expected " << CellValue(col, row);
        }
      }
    }
    EXPECT_EQ(wrong, 0u);
  }

  test::ScratchDir dir_;
};

RasterShape WithUtm33(RasterShape shape) {
  shape.crs_wkt = gis::testing::EpsgWkt2(32633);
  return shape;
}

TEST_F(RasterWriterTest, TiledGTiffHoldsEveryValueAndTheGeoreferencing) {
  const std::string path =
      Write("dem.tif", {.driver = "GTiff"}, WithUtm33(TestShape()));
  ExpectTestRaster(path, 256);
  EXPECT_THAT(dir_.Entries(), ElementsAre("dem.tif"));
}

TEST_F(RasterWriterTest, CogIsACloudOptimizedCopyAndLeavesNoTemporary) {
  const std::string path =
      Write("dem.tif", {.driver = "COG"}, WithUtm33(TestShape()));
  ExpectTestRaster(path, 512);  // the COG driver's default block size
  const GDALDatasetUniquePtr dataset = Reopen(path);
  ASSERT_NE(dataset, nullptr);
  const char* layout = dataset->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE");
  ASSERT_NE(layout, nullptr);
  EXPECT_STREQ(layout, "COG");
  EXPECT_THAT(dir_.Entries(), ElementsAre("dem.tif"));
}

TEST_F(RasterWriterTest, CreationOptionsReachTheDriver) {
  const std::string gtiff =
      Write("small_tiles.tif",
            {.driver = "GTiff",
             .creation_options = {"BLOCKXSIZE=128", "BLOCKYSIZE=128",
                                  "COMPRESS=DEFLATE"}},
            WithUtm33(TestShape()));
  ExpectTestRaster(gtiff, 128);
  const std::string cog = Write(
      "cog.tif",
      {.driver = "COG", .creation_options = {"BLOCKSIZE=256", "COMPRESS=ZSTD"}},
      WithUtm33(TestShape()));
  ExpectTestRaster(cog, 256);
  for (const auto& [path, compression] :
       {std::pair{gtiff, "DEFLATE"}, std::pair{cog, "ZSTD"}}) {
    const GDALDatasetUniquePtr dataset = Reopen(path);
    ASSERT_NE(dataset, nullptr);
    const char* got =
        dataset->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE");
    ASSERT_NE(got, nullptr) << path;
    EXPECT_STREQ(got, compression) << path;
  }
}

TEST_F(RasterWriterTest, GdalinfoOpensItWithCrsGeotransformAndNodata) {
  for (const char* driver : {"GTiff", "COG"}) {
    const std::string path = Write(std::string(driver) + ".tif",
                                   {.driver = driver}, WithUtm33(TestShape()));
    const test::BinaryResult info = test::RunBinary(GDALINFO_PATH, {path});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_THAT(info.out, HasSubstr("Size is 300, 270")) << driver;
    EXPECT_THAT(info.out, HasSubstr("WGS 84 / UTM zone 33N")) << driver;
    EXPECT_THAT(info.out, HasSubstr("ID[\"EPSG\",32633]")) << driver;
    EXPECT_THAT(info.out, HasSubstr("Origin = (500000.000000000000000,"
                                    "5500000.000000000000000)"))
        << driver;
    EXPECT_THAT(info.out, HasSubstr("Pixel Size = (10.000000000000000,"
                                    "-20.000000000000000)"))
        << driver;
    EXPECT_THAT(info.out, HasSubstr("Type=Float64")) << driver;
    EXPECT_THAT(info.out, HasSubstr("NoData Value=-9999")) << driver;
  }
}

TEST_F(RasterWriterTest, NanNodataAndNoCrs) {
  RasterShape shape = TestShape();
  shape.nodata = std::numeric_limits<double>::quiet_NaN();
  const std::string path = PathOf("nan.tif");
  std::unique_ptr<RasterWriter> writer;
  ASSERT_TRUE(
      RasterWriter::Open(path, shape, {.driver = "GTiff"}, &writer).ok());
  const std::vector<double> row(shape.width, 1.5);
  ASSERT_TRUE(writer->WriteRows(0, 1, row).ok());
  ASSERT_TRUE(writer->Close().ok());
  const GDALDatasetUniquePtr dataset = Reopen(path);
  ASSERT_NE(dataset, nullptr);
  EXPECT_EQ(dataset->GetSpatialRef(), nullptr);
  int has_nodata = 0;
  EXPECT_TRUE(
      std::isnan(dataset->GetRasterBand(1)->GetNoDataValue(&has_nodata)));
  EXPECT_TRUE(has_nodata);
  double value = 0;
  ASSERT_EQ(
      dataset->GetRasterBand(1)->RasterIO(GF_Read, 299, 0, 1, 1, &value, 1, 1,
                                          GDT_Float64, 0, 0, nullptr),
      CE_None);
  EXPECT_EQ(value, 1.5);
}

// Open() fails with `code` and a message containing `text`, and leaves no
// file behind.
void ExpectOpenFails(const std::string& path, const RasterShape& shape,
                     const RasterFormat& format, Status::Code code,
                     const std::string& text) {
  std::unique_ptr<RasterWriter> writer;
  const Status status = RasterWriter::Open(path, shape, format, &writer);
  EXPECT_EQ(status.code(), code) << status.ToString();
  EXPECT_THAT(status.message(), HasSubstr(text));
  EXPECT_EQ(writer, nullptr);
}

TEST_F(RasterWriterTest, UnwritablePathNamesTheFileAndGdalsReason) {
  for (const char* driver : {"GTiff", "COG"}) {
    const std::string path = PathOf("no/such/dir/dem.tif");
    std::unique_ptr<RasterWriter> writer;
    const Status status =
        RasterWriter::Open(path, TestShape(), {.driver = driver}, &writer);
    EXPECT_EQ(status.code(), Status::Code::kIOError) << driver;
    EXPECT_THAT(status.message(), StartsWith(path + ": cannot create: "));
    // GDAL's own message follows.
    EXPECT_THAT(status.message(), HasSubstr("No such file or directory"))
        << status.message();
  }
  EXPECT_TRUE(dir_.Entries().empty());
}

TEST_F(RasterWriterTest, UnknownFormatAndBadCreationOptions) {
  const std::string path = PathOf("dem.tif");
  ExpectOpenFails(path, TestShape(), {.driver = "PNG"},
                  Status::Code::kInvalidArgument,
                  "unknown raster format 'PNG': GTiff or COG");
  ExpectOpenFails(
      path, TestShape(), {.driver = "GTiff", .creation_options = {"NO_SUCH=1"}},
      Status::Code::kInvalidArgument, "bad GTiff creation option: ");
  ExpectOpenFails(path, TestShape(),
                  {.driver = "GTiff", .creation_options = {"NO_SUCH=1"}},
                  Status::Code::kInvalidArgument, "NO_SUCH");
  ExpectOpenFails(path, TestShape(),
                  {.driver = "COG", .creation_options = {"COMPRESS=BOGUS"}},
                  Status::Code::kInvalidArgument, "BOGUS");
  // TILED is a GTiff option, not a COG one.
  ExpectOpenFails(path, TestShape(),
                  {.driver = "COG", .creation_options = {"TILED=YES"}},
                  Status::Code::kInvalidArgument, "TILED");
  ExpectOpenFails(path, TestShape(),
                  {.driver = "GTiff", .creation_options = {"COMPRESS"}},
                  Status::Code::kInvalidArgument,
                  "creation option 'COMPRESS' is not NAME=VALUE");
  ExpectOpenFails(path, TestShape(),
                  {.driver = "GTiff", .creation_options = {"=LZW"}},
                  Status::Code::kInvalidArgument, "is not NAME=VALUE");
  EXPECT_TRUE(dir_.Entries().empty());
}

TEST_F(RasterWriterTest, BadShapesAndWkt) {
  const std::string path = PathOf("dem.tif");
  RasterShape empty = TestShape();
  empty.height = 0;
  ExpectOpenFails(path, empty, {.driver = "GTiff"},
                  Status::Code::kInvalidArgument,
                  "at least one row and one column, not 300 x 0");
  RasterShape huge = TestShape();
  huge.width = 1u << 31;
  ExpectOpenFails(path, huge, {.driver = "GTiff"},
                  Status::Code::kInvalidArgument,
                  "GDAL takes at most 2147483647 rows and columns, not "
                  "2147483648 x 270");
  RasterShape flat = TestShape();
  flat.cell_height = 0;
  ExpectOpenFails(path, flat, {.driver = "GTiff"},
                  Status::Code::kInvalidArgument, "cell size must be positive");
  RasterShape nowhere = TestShape();
  nowhere.box.min_x = std::numeric_limits<double>::infinity();
  ExpectOpenFails(path, nowhere, {.driver = "GTiff"},
                  Status::Code::kInvalidArgument, "origin");
  RasterShape bad_crs = TestShape();
  bad_crs.crs_wkt = "PROJCRS[nonsense";
  for (const char* driver : {"GTiff", "COG"}) {
    ExpectOpenFails(path, bad_crs, {.driver = driver},
                    Status::Code::kInvalidArgument,
                    path + ": the CRS is not WKT GDAL reads");
  }
  EXPECT_TRUE(dir_.Entries().empty());
}

TEST_F(RasterWriterTest, RowsOutsideTheRasterOrOfTheWrongSize) {
  std::unique_ptr<RasterWriter> writer;
  ASSERT_TRUE(RasterWriter::Open(PathOf("dem.tif"), TestShape(),
                                 {.driver = "GTiff"}, &writer)
                  .ok());
  const std::vector<double> two_rows(600, 1.0);
  Status status = writer->WriteRows(269, 2, two_rows);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("rows 269 + 2 outside the raster"));
  status = writer->WriteRows(270, 0, {});
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  status = writer->WriteRows(0, 3, two_rows);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("600 values for 3 rows of 300"));
  EXPECT_TRUE(writer->WriteRows(268, 2, two_rows).ok());
  ASSERT_TRUE(writer->Close().ok());
  status = writer->WriteRows(0, 2, two_rows);
  EXPECT_EQ(status.code(), Status::Code::kFailedPrecondition);
  EXPECT_EQ(writer->Close().code(), Status::Code::kFailedPrecondition);
  // Closed: the file stays.
  writer.reset();
  EXPECT_THAT(dir_.Entries(), ElementsAre("dem.tif"));
}

TEST_F(RasterWriterTest, AWriterNotClosedRemovesItsFiles) {
  for (const char* driver : {"GTiff", "COG"}) {
    std::unique_ptr<RasterWriter> writer;
    ASSERT_TRUE(RasterWriter::Open(PathOf("dem.tif"), TestShape(),
                                   {.driver = driver}, &writer)
                    .ok());
    ASSERT_TRUE(writer->WriteRows(0, 1, std::vector<double>(300, 2.0)).ok());
    EXPECT_FALSE(dir_.Entries().empty());
    writer.reset();
    EXPECT_TRUE(dir_.Entries().empty()) << driver;
  }
}

TEST(CheckRasterFormatTest, JudgesFormatsAsOpenDoesWithoutAFile) {
  EXPECT_TRUE(CheckRasterFormat({.driver = "GTiff"}).ok());
  EXPECT_TRUE(CheckRasterFormat(
                  {.driver = "COG", .creation_options = {"COMPRESS=DEFLATE"}})
                  .ok());
  Status status = CheckRasterFormat({.driver = "HFA"});
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(status.message(), "unknown raster format 'HFA': GTiff or COG");
  status = CheckRasterFormat(
      {.driver = "GTiff", .creation_options = {"COMPRESS=NONSENSE"}});
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  // GDAL's own words, naming the option and the value.
  EXPECT_THAT(status.message(), StartsWith("bad GTiff creation option: "));
  EXPECT_THAT(status.message(), HasSubstr("NONSENSE"));
  EXPECT_THAT(status.message(), HasSubstr("COMPRESS"));
}

TEST(DefaultRasterDriverTest, IsCogOnBookwormsGdal) {
  // GDAL 3.6 has the COG driver; GTiff is the default only without it.
  EXPECT_EQ(DefaultRasterDriver(), "COG");
}

}  // namespace
}  // namespace locator::gis
