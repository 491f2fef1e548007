// locatord end to end on a GeoPackage made at test time: a synthetic hill
// in UTM zone 33N (EPSG:32633) with z, served by the real binary, answers
// checked against CGAL's own locate() on the same points, the CRS checked in
// GetStats, and GIS specs through the Reload path.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/gis/ogr_dataset.h"
#include "server/core/triangulation.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/e2e_support.h"

namespace locator::e2e {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr int kHillSide = 15;  // 225 points, 400 m apart

class LocatordGisTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    const std::string geojson = dir_->path() + "/hill.geojson";
    gis::testing::WriteFile(
        geojson, gis::testing::PointsGeoJson(gis::testing::UtmHill(kHillSide)));
    gpkg_ = new std::string(dir_->path() + "/hill.gpkg");
    gis::testing::Ogr2Ogr({"-f", "GPKG", *gpkg_, geojson, "-nln", "hill",
                           "-a_srs", "EPSG:32633"});
    ASSERT_TRUE(gis::LoadOgrDataset(*gpkg_, &reference_points_).ok());
    ASSERT_TRUE(Triangulation::Build(reference_points_, &reference_).ok());
    const Status started = StartLocatord(*gpkg_, {}, &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }
  static void TearDownTestSuite() {
    server_.reset();
    reference_.reset();
    delete gpkg_;
    delete dir_;
  }

  void SetUp() override {
    ASSERT_NE(server_, nullptr);
    stub_ = NewStub(*server_);
  }

  static test::ScratchDir* dir_;
  static std::string* gpkg_;
  static Dataset reference_points_;
  static std::unique_ptr<Triangulation> reference_;
  static std::unique_ptr<testing::ServerProcess> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

test::ScratchDir* LocatordGisTest::dir_ = nullptr;
std::string* LocatordGisTest::gpkg_ = nullptr;
Dataset LocatordGisTest::reference_points_;
std::unique_ptr<Triangulation> LocatordGisTest::reference_;
std::unique_ptr<testing::ServerProcess> LocatordGisTest::server_;

grpc::Status Reload(v1::Locator::Stub& stub, const std::string& dataset,
                    v1::ReloadResponse* response) {
  grpc::ClientContext context;
  v1::ReloadRequest request;
  request.set_dataset(dataset);
  return stub.Reload(&context, request, response);
}

TEST_F(LocatordGisTest, AnswersAgreeWithCgalAndCarryTheHillsHeights) {
  std::vector<Point2> queries = reference_points_.points;  // every vertex
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      // Across the hill and 1 km beyond it on every side.
      queries.push_back({497000 + i * 150.0 + 0.25, 5497000 + j * 150.0});
    }
  }
  size_t with_value = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    const Point2& q = queries[i];
    v1::LocateResponse response;
    const grpc::Status status = LocateOne(*stub_, q, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    const LocateResult got = FromLocateResponse(response);
    const LocateResult expected = reference_->ReferenceLocate(q);
    ASSERT_TRUE(reference_->Agrees(q, got, expected))
        << "query " << i << " (" << q.x << ", " << q.y << ")";
    ASSERT_EQ(got.has_value, expected.has_value) << "query " << i;
    if (got.has_value) {
      ++with_value;
      EXPECT_NEAR(got.value, expected.value, 1e-9 * std::abs(expected.value));
      // A point of the hill: between its foot (400 m) and its top (700 m).
      EXPECT_GE(got.value, 400 - 1e-9);
      EXPECT_LE(got.value, 700 + 1e-9);
    }
  }
  // The vertices and most of the grid lie on the hill.
  EXPECT_GT(with_value, reference_points_.points.size() + 500);
}

TEST_F(LocatordGisTest, GetStatsReportsTheCrs) {
  const v1::GetStatsResponse stats = GetStats(*stub_);
  const v1::CrsStats& crs = stats.dataset().crs();
  EXPECT_EQ(crs.name(), "WGS 84 / UTM zone 33N");
  EXPECT_EQ(crs.epsg_code(), 32633u);
  EXPECT_THAT(crs.axis_units(), ElementsAre("metre", "metre"));
  EXPECT_THAT(crs.wkt(), HasSubstr("UTM zone 33N"));
  EXPECT_EQ(stats.dataset().input_points(),
            static_cast<uint64_t>(kHillSide * kHillSide));
  EXPECT_TRUE(stats.dataset().has_values());
}

TEST_F(LocatordGisTest, ReloadTakesGisSpecsAndNamesTheirErrors) {
  v1::ReloadResponse response;
  grpc::Status status = Reload(*stub_, *gpkg_ + "?layer=nope", &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_THAT(status.error_message(),
              HasSubstr(*gpkg_ + ": no layer 'nope' (layers: 'hill')"));

  // The northern half of the hill, assigned UTM zone 32N.
  status = Reload(*stub_,
                  *gpkg_ + "?where=id%20%25%2015%20%3E%3D%207&a_srs=EPSG:32632",
                  &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().input_points(), 8u * kHillSide);
  EXPECT_EQ(response.dataset().crs().epsg_code(), 32632u);
  EXPECT_EQ(GetStats(*stub_).dataset().crs().name(), "WGS 84 / UTM zone 32N");

  // A generator has no CRS.
  status = Reload(*stub_, "uniform:1000:3", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_FALSE(GetStats(*stub_).dataset().has_crs());

  // Back to the original for the other tests.
  ASSERT_TRUE(Reload(*stub_, *gpkg_, &response).ok());
  EXPECT_EQ(response.dataset().crs().epsg_code(), 32633u);
}

}  // namespace
}  // namespace locator::e2e
