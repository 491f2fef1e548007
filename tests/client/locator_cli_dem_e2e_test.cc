// End to end: a raster DEM served within a stated error and rendered back.
// A GeoTIFF made at test time (a UTM hill with a nodata hole and a nodata
// corner) is served by the real locatord as dem.tif?max_error=E; the real
// `locator grid` renders it at the DEM's own pixel centres (its outer edges
// and size), and every pixel of the result is within E of the DEM where the
// DEM has a value and nodata where it has none. The largest difference found
// is the server's certificate, checked by brute force. `locator stats`
// prints the certificate, and a lon/lat locate gets the DEM's value.

#include <gdal_priv.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/common/gis/raster_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/server_process.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::RunBinary;
using test::ServerProcess;
using ::testing::HasSubstr;

constexpr uint32_t kWidth = 72;
constexpr uint32_t kHeight = 54;
constexpr double kCell = 25;       // metres
constexpr double kMaxError = 0.5;  // metres
constexpr double kNodata = -9999;

class LocatorCliDemTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    GDALAllRegister();
    dir_ = new test::ScratchDir();
    dem_ = new gis::testing::DemFixture(
        gis::testing::HillDem(kWidth, kHeight, kCell));
    gis::testing::PunchHole(dem_, 30, 20, 38, 27);  // inside: a hole
    gis::testing::PunchHole(dem_, 0, 0, 5, 4);      // a corner cut off
    path_ = new std::string(dir_->path() + "/dem.tif");
    gis::testing::WriteDem(*path_, *dem_);
    const std::string spec =
        "dem=" + *path_ + "?max_error=" + std::to_string(kMaxError);
    const Status started = ServerProcess::Start(
        LOCATORD_PATH, {"--dataset", spec, "--listen", "127.0.0.1:0"},
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }
  static void TearDownTestSuite() {
    server_.reset();
    delete path_;
    delete dem_;
    delete dir_;
  }

  static BinaryResult Locator(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target()};
    all.insert(all.end(), args.begin(), args.end());
    return RunBinary(LOCATOR_PATH, all);
  }
  static bool IsNodata(double v) { return v == kNodata || std::isnan(v); }

  static test::ScratchDir* dir_;
  static gis::testing::DemFixture* dem_;
  static std::string* path_;
  static std::unique_ptr<ServerProcess> server_;
};

test::ScratchDir* LocatorCliDemTest::dir_ = nullptr;
gis::testing::DemFixture* LocatorCliDemTest::dem_ = nullptr;
std::string* LocatorCliDemTest::path_ = nullptr;
std::unique_ptr<ServerProcess> LocatorCliDemTest::server_;

TEST_F(LocatorCliDemTest, GridAtThePixelCentresIsTheDemWithinMaxError) {
  const auto& gt = dem_->geotransform;
  const std::string out = dir_->path() + "/rendered.tif";
  const BinaryResult result = Locator(
      {"--dataset", "dem", "grid", "--te", std::to_string(gt[0]),
       std::to_string(gt[3] + kHeight * gt[5]),
       std::to_string(gt[0] + kWidth * gt[1]), std::to_string(gt[3]),
       "--outsize", std::to_string(kWidth), std::to_string(kHeight),
       "--a_nodata", std::to_string(kNodata), "--of", "GTiff", "--out", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const GDALDatasetUniquePtr rendered(
      GDALDataset::Open(out.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  ASSERT_NE(rendered, nullptr);
  double got_gt[6];
  ASSERT_EQ(rendered->GetGeoTransform(got_gt), CE_None);
  for (int i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(got_gt[i], gt[i]) << i;
  std::vector<double> values(size_t{kWidth} * kHeight);
  ASSERT_EQ(rendered->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, kWidth, kHeight,
                                                 values.data(), kWidth, kHeight,
                                                 GDT_Float64, 0, 0, nullptr),
            CE_None);
  double largest = 0;
  size_t valid = 0, wrong = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    const double want = dem_->values[i];
    const double got = values[i];
    const bool want_value = want != kNodata;
    if (want_value) ++valid;
    const bool ok =
        want_value ? !IsNodata(got) && std::abs(got - want) <= kMaxError + 1e-9
                   : IsNodata(got);
    if (!ok && ++wrong <= 5) {
      ADD_FAILURE() << "pixel (" << i % kWidth << ", " << i / kWidth
                    << "): DEM " << want << ", served " << got;
    }
    if (want_value && !IsNodata(got)) {
      largest = std::max(largest, std::abs(got - want));
    }
  }
  EXPECT_EQ(wrong, 0u);

  // The certificate is the largest difference at the pixels, and no more
  // than asked for; the TIN is far smaller than the DEM.
  const BinaryResult stats = Locator({"--json", "--dataset", "dem", "stats"});
  ASSERT_EQ(stats.exit_code, 0) << stats.err;
  EXPECT_THAT(stats.out, HasSubstr("\"simplification\""));
  const BinaryResult text = Locator({"--dataset", "dem", "stats"});
  EXPECT_THAT(text.out, HasSubstr("simplified   " + std::to_string(valid) +
                                  " samples to "));
  const std::string marker = "\"max_error\":";
  const size_t at = stats.out.find(marker);
  ASSERT_NE(at, std::string::npos) << stats.out;
  const double certified = std::stod(stats.out.substr(at + marker.size()));
  EXPECT_LE(certified, kMaxError);
  EXPECT_NEAR(largest, certified, 1e-6);
}

TEST_F(LocatorCliDemTest, ALonLatLocateGetsTheDemsValue) {
  // Pixel (50, 12): its centre in UTM, then in lon/lat by cs2cs.
  const auto& gt = dem_->geotransform;
  const Point2 utm{gt[0] + 50.5 * gt[1], gt[3] + 12.5 * gt[5]};
  const std::vector<Point2> lon_lat =
      gis::testing::Cs2cs({utm}, "EPSG:32633", "EPSG:4326", dir_->path());
  ASSERT_EQ(lon_lat.size(), 1u);
  char x[32], y[32];
  std::snprintf(x, sizeof(x), "%.17g", lon_lat[0].x);
  std::snprintf(y, sizeof(y), "%.17g", lon_lat[0].y);
  const BinaryResult result = Locator(
      {"--json", "--dataset", "dem", "--crs", "EPSG:4326", "locate", x, y});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string marker = "\"value\":";
  const size_t at = result.out.find(marker);
  ASSERT_NE(at, std::string::npos) << result.out;
  // cs2cs prints 12 decimals of a degree (0.1 micrometre): the point is the
  // pixel's centre, within the error bound.
  EXPECT_NEAR(std::stod(result.out.substr(at + marker.size())),
              dem_->values[12 * kWidth + 50], kMaxError + 1e-4);
}

}  // namespace
}  // namespace locator
