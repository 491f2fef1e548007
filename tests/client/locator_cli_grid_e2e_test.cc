// End to end: `locator profile` and `locator grid` (the real binary) against
// the fake server of this process, whose answers are computed from the
// request (fake_locator_server.h). Checks the requests the flags make, the
// GeoTIFF written (every streamed value at its place, the CRS, the
// geotransform, nodata, tiling), what is printed, and the errors.

#include <gdal_priv.h>
#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/client/fake_locator_server.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/testing/run_binary.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::FakeGridValue;
using test::FakeLocatorServer;
using test::RunBinary;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

class LocatorCliGridTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    GDALAllRegister();
    server_ = new FakeLocatorServer(gis::testing::EpsgWkt2(32633));
  }
  static void TearDownTestSuite() { delete server_; }

  // Runs `locator --target <fake> args...`.
  static BinaryResult Locator(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target()};
    all.insert(all.end(), args.begin(), args.end());
    return RunBinary(LOCATOR_PATH, all);
  }

  std::string PathOf(const std::string& name) const {
    return dir_.path() + "/" + name;
  }

  // Checks that `path` holds exactly the fake's raster for `request`: size,
  // geotransform, CRS, nodata and every cell.
  static void ExpectFakeRaster(const std::string& path, uint32_t width,
                               uint32_t height, const double transform[6],
                               double nodata, int block_size) {
    const GDALDatasetUniquePtr dataset(
        GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    ASSERT_NE(dataset, nullptr) << path;
    ASSERT_EQ(dataset->GetRasterXSize(), static_cast<int>(width));
    ASSERT_EQ(dataset->GetRasterYSize(), static_cast<int>(height));
    double got[6];
    ASSERT_EQ(dataset->GetGeoTransform(got), CE_None);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(got[i], transform[i]) << i;
    ASSERT_NE(dataset->GetSpatialRef(), nullptr);
    EXPECT_STREQ(dataset->GetSpatialRef()->GetAuthorityCode(nullptr), "32633");
    GDALRasterBand* band = dataset->GetRasterBand(1);
    int has_nodata = 0;
    const double got_nodata = band->GetNoDataValue(&has_nodata);
    EXPECT_TRUE(has_nodata);
    EXPECT_TRUE(got_nodata == nodata ||
                (std::isnan(got_nodata) && std::isnan(nodata)))
        << got_nodata;
    int block_x = 0, block_y = 0;
    band->GetBlockSize(&block_x, &block_y);
    EXPECT_EQ(block_x, block_size);
    EXPECT_EQ(block_y, block_size);
    std::vector<double> values(size_t{width} * height);
    ASSERT_EQ(band->RasterIO(GF_Read, 0, 0, width, height, values.data(), width,
                             height, GDT_Float64, 0, 0, nullptr),
              CE_None);
    size_t wrong = 0;
    for (uint32_t row = 0; row < height; ++row) {
      for (uint32_t col = 0; col < width; ++col) {
        const double expected = FakeGridValue(col, row, nodata);
        const double value = values[size_t{row} * width + col];
        const bool same =
            value == expected || (std::isnan(value) && std::isnan(expected));
        if (!same && ++wrong <= 5) {
          ADD_FAILURE() << "cell (" << col << ", " << row << "): " << value
                        << ", expected " << expected;
        }
      }
    }
    EXPECT_EQ(wrong, 0u);
  }

  static FakeLocatorServer* server_;
  test::ScratchDir dir_;
};

FakeLocatorServer* LocatorCliGridTest::server_ = nullptr;

TEST_F(LocatorCliGridTest, GridWritesEveryStreamedValueAtItsPlace) {
  const std::string out = PathOf("dem.tif");
  // 37 x 20: seven messages of 3 rows (the last with 2), last rows first.
  const BinaryResult result = Locator(
      {"grid", "--te", "500000", "5499800", "500370", "5500000", "--outsize",
       "37", "20", "--a_nodata", "-9999", "--of", "GTiff", "--out", out,
       "--dataset", "terrain", "--interpolation", "natural-neighbor"});
  ASSERT_EQ(result.exit_code, 0) << result.err;

  const v1::GridRequest request = server_->last_grid();
  EXPECT_EQ(request.dataset(), "terrain");
  EXPECT_EQ(request.box().min_x(), 500000);
  EXPECT_EQ(request.box().min_y(), 5499800);
  EXPECT_EQ(request.box().max_x(), 500370);
  EXPECT_EQ(request.box().max_y(), 5500000);
  EXPECT_EQ(request.width(), 37u);
  EXPECT_EQ(request.height(), 20u);
  EXPECT_EQ(request.cell_size(), 0);
  ASSERT_TRUE(request.has_nodata());
  EXPECT_EQ(request.nodata(), -9999);
  EXPECT_EQ(request.interpolation(), v1::INTERPOLATION_NATURAL_NEIGHBOR);

  const double transform[6] = {500000, 10, 0, 5500000, 0, -10};
  ExpectFakeRaster(out, 37, 20, transform, -9999, 256);
  // 37 x 20 cells, every fifth diagonal without a value: 148 of them.
  EXPECT_THAT(result.out, StartsWith("wrote " + out +
                                     ": 37 x 20 GTiff, 592 cells with "
                                     "values, "));
  EXPECT_THAT(result.out, ::testing::EndsWith(" s\n"));
}

TEST_F(LocatorCliGridTest, CogByDefaultWithTheCellSizeAndNanNodata) {
  const std::string out = PathOf("dem_cog.tif");
  // --tr 7 over a 100 x 50 box: 15 x 8 cells, the box grown to 105 x 56.
  const BinaryResult result =
      Locator({"grid", "--te", "-50", "-20", "50", "30", "--tr", "7", "7",
               "--co", "BLOCKSIZE=128", "--out", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const v1::GridRequest request = server_->last_grid();
  EXPECT_EQ(request.cell_size(), 7);
  EXPECT_EQ(request.width(), 0u);
  EXPECT_EQ(request.height(), 0u);
  EXPECT_FALSE(request.has_nodata());
  EXPECT_EQ(request.dataset(), "");
  EXPECT_EQ(request.interpolation(), v1::INTERPOLATION_UNSPECIFIED);

  const double transform[6] = {-50, 7, 0, 30, 0, -7};
  ExpectFakeRaster(out, 15, 8, transform, std::nan(""), 128);
  const GDALDatasetUniquePtr dataset(
      GDALDataset::Open(out.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  ASSERT_NE(dataset, nullptr);
  const char* layout = dataset->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE");
  ASSERT_NE(layout, nullptr);
  EXPECT_STREQ(layout, "COG");
  EXPECT_THAT(result.out, HasSubstr(": 15 x 8 COG, 96 cells with values"));
  // The temporary GTiff is gone.
  EXPECT_THAT(dir_.Entries(), ElementsAre("dem_cog.tif"));
}

TEST_F(LocatorCliGridTest, WithoutTeTheBoxIsTheDatasetsBoundingBox) {
  const std::string out = PathOf("whole.tif");
  const BinaryResult result = Locator(
      {"--dataset", "bedrock", "grid", "--outsize", "6", "4", "--out", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(server_->last_get_stats().dataset(), "bedrock");
  const v1::GridRequest request = server_->last_grid();
  EXPECT_EQ(request.dataset(), "bedrock");
  EXPECT_EQ(request.box().min_x(), test::kFakeBox[0]);
  EXPECT_EQ(request.box().min_y(), test::kFakeBox[1]);
  EXPECT_EQ(request.box().max_x(), test::kFakeBox[2]);
  EXPECT_EQ(request.box().max_y(), test::kFakeBox[3]);
  const double transform[6] = {100, 10, 0, 240, 0, -10};
  ExpectFakeRaster(out, 6, 4, transform, std::nan(""), 512);
}

TEST_F(LocatorCliGridTest, ServerErrorsPrintClearlyAndLeaveNoFile) {
  const std::string out = PathOf("dem.tif");
  const std::vector<std::string> args = {"grid", "--te",  "0",         "0",
                                         "10",   "10",    "--outsize", "10",
                                         "10",   "--out", out};
  server_->FailNextGrid(grpc::Status(grpc::StatusCode::RESOURCE_EXHAUSTED,
                                     "100000000 cells exceed the limit of "
                                     "16777216"));
  BinaryResult result = Locator(args);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err,
            "error: RESOURCE_EXHAUSTED: 100000000 cells exceed the limit of "
            "16777216\n");
  EXPECT_EQ(result.out, "");

  server_->FailNextGrid(grpc::Status(grpc::StatusCode::INVALID_ARGUMENT,
                                     "box: min_x must be below max_x"));
  result = Locator(args);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err,
            "error: INVALID_ARGUMENT: box: min_x must be below max_x\n");

  // Fails after the first rows were written: the partial file is removed.
  server_->FailNextGrid(
      grpc::Status(grpc::StatusCode::DEADLINE_EXCEEDED, "too slow"),
      test::GridFault::kFailAfterFirstMessage);
  result = Locator(args);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err, "error: DEADLINE_EXCEEDED: too slow\n");

  // Ends OK with rows missing: the server broke the contract.
  server_->FailNextGrid(grpc::Status::OK, test::GridFault::kDropLastMessage);
  result = Locator(args);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err,
            "error: INTERNAL: the server's grid stream: ended after 7 of 10 "
            "rows\n");
  EXPECT_TRUE(dir_.Entries().empty());
}

TEST_F(LocatorCliGridTest, AnUnwritableFileIsAnInputError) {
  const std::string out = PathOf("no/such/dir/dem.tif");
  const BinaryResult result = Locator({"grid", "--te", "0", "0", "10", "10",
                                       "--outsize", "10", "10", "--out", out});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, StartsWith("error: " + out + ": cannot create: "));
  EXPECT_THAT(result.err, HasSubstr("No such file or directory"));
}

TEST_F(LocatorCliGridTest, FormatProblemsAreUsageErrorsBeforeAnyCall) {
  const uint64_t calls = server_->calls();
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{
           {"--of", "PNG"}, {"--co", "COMPRESS=NONSENSE"}, {"--co", "TILED"}}) {
    std::vector<std::string> line = {"grid", "--outsize", "2",
                                     "2",    "--out",     PathOf("x.tif")};
    line.insert(line.end(), args.begin(), args.end());
    const BinaryResult result = Locator(line);
    EXPECT_EQ(result.exit_code, 2) << args[1];
    EXPECT_THAT(result.err, HasSubstr("usage: locator")) << args[1];
  }
  EXPECT_EQ(server_->calls(), calls);
  EXPECT_TRUE(dir_.Entries().empty());
}

TEST_F(LocatorCliGridTest, ProfilePrintsBreakpointsSamplesAndGaps) {
  const BinaryResult result = Locator(
      {"profile", "--line", "0,0 30,40 30,0", "--samples", "3", "--crs",
       "EPSG:32633", "--dataset", "terrain", "--interpolation", "nearest"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const v1::ProfileRequest request = server_->last_profile();
  ASSERT_EQ(request.vertices_size(), 3);
  EXPECT_EQ(request.vertices(1).x(), 30);
  EXPECT_EQ(request.vertices(1).y(), 40);
  EXPECT_EQ(request.vertices(2).y(), 0);
  EXPECT_EQ(request.samples(), 3u);
  EXPECT_EQ(request.crs(), "EPSG:32633");
  EXPECT_EQ(request.dataset(), "terrain");
  EXPECT_EQ(request.interpolation(), v1::INTERPOLATION_NEAREST);

  // Length 50 + 40; breakpoints at 0, 25, 50, 70, 90; the gap from 67.5.
  const std::vector<std::string> lines = Lines(result.out);
  ASSERT_GE(lines.size(), 16u) << result.out;
  EXPECT_EQ(lines[0], "length       90");
  EXPECT_EQ(lines[1], "crossings    2");
  EXPECT_EQ(lines[2], "breakpoints  5");
  EXPECT_THAT(lines[3], StartsWith("  distance  x"));
  EXPECT_EQ(lines[4], "  0         0   0   1000  0         LINE_VERTEX");
  EXPECT_EQ(lines[5], "  25        15  20  1055  1         EDGE_CROSSING");
  EXPECT_EQ(lines[8], "  90        30  0   none  -1        LINE_VERTEX");
  EXPECT_EQ(lines[9], "samples  3");
  EXPECT_EQ(lines[12], "  45        27  36  1099  0");
  EXPECT_EQ(lines[13], "  90        30  0   none  -1");
  EXPECT_EQ(lines.back(), "  67.5  90  OUTSIDE_CONVEX_HULL");
}

TEST_F(LocatorCliGridTest, ProfileAsJsonAndCsv) {
  BinaryResult result =
      Locator({"profile", "--line", "LINESTRING (0 0, 30 40)", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  v1::ProfileResponse response;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, &response).ok())
      << result.out;
  v1::ProfileRequest request;
  for (auto [x, y] : {std::pair{0.0, 0.0}, std::pair{30.0, 40.0}}) {
    v1::Point* vertex = request.add_vertices();
    vertex->set_x(x);
    vertex->set_y(y);
  }
  EXPECT_EQ(response.SerializeAsString(),
            test::FakeProfile(request).SerializeAsString());

  result =
      Locator({"profile", "--line", "0,0 30,40", "--csv", "--samples", "2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out,
            "kind,distance,x,y,z,triangle_id,segment\n"
            "LINE_VERTEX,0,0,0,1000,0,0\n"
            "SAMPLE,0,0,0,1000,0,0\n"
            "EDGE_CROSSING,25,15,20,1055,1,0\n"
            "LINE_VERTEX,50,30,40,,-1,0\n"
            "SAMPLE,50,30,40,,-1,0\n");
}

TEST_F(LocatorCliGridTest, ProfileErrorsPrintClearly) {
  server_->FailNextProfile(
      grpc::Status(grpc::StatusCode::RESOURCE_EXHAUSTED,
                   "the line crosses more than 1000000 triangle edges"));
  BinaryResult result = Locator({"profile", "--line", "0,0 1,1"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err,
            "error: RESOURCE_EXHAUSTED: the line crosses more than 1000000 "
            "triangle edges\n");
  server_->FailNextProfile(grpc::Status(grpc::StatusCode::INVALID_ARGUMENT,
                                        "vertex 1 is not finite"));
  result = Locator({"profile", "--line", "0,0 nan,1"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err, "error: INVALID_ARGUMENT: vertex 1 is not finite\n");
  result = Locator({"profile", "--line", "0,0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err,
              StartsWith("error: --line '0,0': a line needs at least 2 "
                         "vertices"));
}

}  // namespace
}  // namespace locator
