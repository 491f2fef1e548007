// End to end: the real `locator` binary against a real locatord serving a
// GeoPackage in UTM zone 33N (EPSG:32633), made at test time with ogr2ogr.
// Queries sent in lon/lat with --crs EPSG:4326 must get the answers of the
// same points projected by cs2cs beforehand; --dataset "" is the default
// dataset; stats name the CRS.

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/server_process.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::RunBinary;
using test::ServerProcess;
using ::testing::HasSubstr;

constexpr int kHillSide = 15;  // 225 points, 400 m apart

// Lon/lat points over the hill (centred at 15°E, 49.6525°N), all inside it.
const std::vector<Point2> kLonLat = {
    {15.0, 49.6525}, {15.011, 49.66}, {14.987, 49.6431}, {15.0123, 49.6444}};

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::string Number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

class LocatorCliGisTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    const std::string gpkg =
        gis::testing::UtmHillGeoPackage(kHillSide, dir_->path());
    const Status started = ServerProcess::Start(
        LOCATORD_PATH, {"--dataset", gpkg, "--listen", "127.0.0.1:0"},
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }
  static void TearDownTestSuite() {
    server_.reset();
    delete dir_;
  }

  void SetUp() override { ASSERT_NE(server_, nullptr); }

  // Runs `locator --target <server> args...`; it must succeed.
  static std::string Locator(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target()};
    all.insert(all.end(), args.begin(), args.end());
    const BinaryResult result = RunBinary(LOCATOR_PATH, all);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  }

  static v1::LocateResponse LocateJson(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--json", "locate"};
    all.insert(all.end(), args.begin(), args.end());
    const std::string out = Locator(all);
    v1::LocateResponse response;
    EXPECT_TRUE(
        google::protobuf::util::JsonStringToMessage(out, &response).ok())
        << out;
    return response;
  }

  static test::ScratchDir* dir_;
  static std::unique_ptr<ServerProcess> server_;
};

test::ScratchDir* LocatorCliGisTest::dir_ = nullptr;
std::unique_ptr<ServerProcess> LocatorCliGisTest::server_;

TEST_F(LocatorCliGisTest, LocateInLonLatAnswersAsTheProjectedPoint) {
  const std::vector<Point2> utm =
      gis::testing::Cs2cs(kLonLat, "EPSG:4326", "EPSG:32633", dir_->path());
  ASSERT_EQ(utm.size(), kLonLat.size());
  for (size_t i = 0; i < kLonLat.size(); ++i) {
    const v1::LocateResponse lon_lat =
        LocateJson({Number(kLonLat[i].x), Number(kLonLat[i].y), "--crs",
                    "EPSG:4326", "--dataset", ""});
    const v1::LocateResponse projected =
        LocateJson({Number(utm[i].x), Number(utm[i].y)});
    EXPECT_EQ(lon_lat.type(), v1::LOCATION_TYPE_FACE) << i;
    EXPECT_EQ(lon_lat.triangle_id(), projected.triangle_id()) << i;
    EXPECT_THAT(lon_lat.vertex_ids(),
                ::testing::ElementsAreArray(projected.vertex_ids()))
        << i;
    ASSERT_TRUE(lon_lat.has_value() && projected.has_value()) << i;
    // Both projected by PROJ: the same point to well under a millimetre.
    EXPECT_NEAR(lon_lat.value(), projected.value(), 1e-6) << i;
    EXPECT_GT(lon_lat.value(), 400);  // on the hill
  }
}

TEST_F(LocatorCliGisTest, BatchInLonLatAnswersAsTheProjectedPoints) {
  const std::vector<Point2> utm =
      gis::testing::Cs2cs(kLonLat, "EPSG:4326", "EPSG:32633", dir_->path());
  const auto write = [](const std::string& path,
                        const std::vector<Point2>& points) {
    std::string text = "x,y\n";
    for (const Point2& p : points) {
      text += Number(p.x) + "," + Number(p.y) + "\n";
    }
    gis::testing::WriteFile(path, text);
  };
  const std::string lon_lat_file = dir_->path() + "/lonlat.csv";
  const std::string utm_file = dir_->path() + "/utm.csv";
  write(lon_lat_file, kLonLat);
  write(utm_file, utm);
  const std::vector<std::string> lon_lat =
      Lines(Locator({"--crs", "EPSG:4326", "batch", lon_lat_file}));
  const std::vector<std::string> projected =
      Lines(Locator({"batch", utm_file}));
  ASSERT_EQ(lon_lat.size(), kLonLat.size() + 1);
  ASSERT_EQ(projected.size(), kLonLat.size() + 1);
  for (size_t i = 1; i < lon_lat.size(); ++i) {
    // type,triangle_id,v0,v1,v2 after the query's own x,y.
    const auto answer = [](const std::string& row) {
      std::string rest = row;
      for (int field = 0; field < 2; ++field) rest.erase(0, rest.find(',') + 1);
      size_t end = 0;
      for (int field = 0; field < 5; ++field) end = rest.find(',', end) + 1;
      return rest.substr(0, end);
    };
    EXPECT_EQ(answer(lon_lat[i]), answer(projected[i])) << lon_lat[i];
    EXPECT_THAT(lon_lat[i], HasSubstr(",FACE,"));
  }
}

TEST_F(LocatorCliGisTest, StatsOfTheDefaultDatasetNameItsCrs) {
  const std::string out = Locator({"--dataset", "", "stats"});
  EXPECT_THAT(out,
              HasSubstr("crs          WGS 84 / UTM zone 33N (EPSG:32633)"));
  EXPECT_THAT(out, HasSubstr("225 read"));
}

TEST_F(LocatorCliGisTest, AnUnknownCrsIsTheServersInvalidArgument) {
  const BinaryResult result =
      RunBinary(LOCATOR_PATH, {"--target", server_->target(), "--crs",
                               "EPSG:999999", "locate", "15", "49.65"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, ::testing::StartsWith("error: INVALID_ARGUMENT: "));
  EXPECT_THAT(result.err, HasSubstr("EPSG:999999"));
}

}  // namespace
}  // namespace locator
