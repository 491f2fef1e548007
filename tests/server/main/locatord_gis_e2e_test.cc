// locatord end to end on a GeoPackage made at test time: a synthetic hill
// in UTM zone 33N (EPSG:32633) with z, served by the real binary, answers
// checked against CGAL's own locate() on the same points, the CRS checked in
// GetStats, GIS specs through the Reload path, and requests in EPSG:4326
// against the same points projected by cs2cs beforehand. The hill is the
// dataset named "terrain", served beside a default dataset ("bedrock", a
// generator without a CRS), so every hill request names its dataset.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/gis/ogr_dataset.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr int kHillSide = 15;  // 225 points, 400 m apart
// Above the largest batch the tests send (LonLatQueries: 900 points).
constexpr int kMaxBatchPoints = 1000;
// The hill's dataset name, and the default dataset served beside it.
constexpr char kTerrain[] = "terrain";
constexpr char kBedrockSpec[] = "uniform:3000:7";

class LocatordGisTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir();
    gpkg_ = new std::string(
        gis::testing::UtmHillGeoPackage(kHillSide, dir_->path()));
    Dataset points;
    ASSERT_TRUE(gis::LoadOgrDataset(*gpkg_, &points).ok());
    ASSERT_TRUE(Reference::FromDataset(std::move(points), &reference_).ok());
    const Status started = StartLocatord(
        std::string("bedrock=") + kBedrockSpec,
        {"--dataset", std::string(kTerrain) + "=" + *gpkg_, "--reload-dir",
         dir_->path(), "--max-batch-points", std::to_string(kMaxBatchPoints)},
        &server_);
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
  static std::unique_ptr<Reference> reference_;
  static std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

test::ScratchDir* LocatordGisTest::dir_ = nullptr;
std::string* LocatordGisTest::gpkg_ = nullptr;
std::unique_ptr<Reference> LocatordGisTest::reference_;
std::unique_ptr<ServerProcess> LocatordGisTest::server_;

// Lon/lat points over the hill (which is centred at 15°E, 49.6525°N).
std::vector<Point2> LonLatQueries() {
  std::vector<Point2> points;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      points.push_back({14.965 + i * 0.00233, 49.630 + j * 0.00147});
    }
  }
  return points;
}

v1::LocateRequest LonLatRequest(const Point2& q, bool vertices_in_lon_lat) {
  v1::LocateRequest request = LocateRequestFor(q, kTerrain);
  request.set_crs("EPSG:4326");
  request.set_vertices_in_request_crs(vertices_in_lon_lat);
  return request;
}

TEST_F(LocatordGisTest, AnswersAgreeWithCgalAndCarryTheHillsHeights) {
  std::vector<Point2> queries = reference_->dataset().points;  // every vertex
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
    const grpc::Status status = LocateOne(*stub_, q, &response, kTerrain);
    ASSERT_TRUE(status.ok()) << status.error_message();
    const LocateResult got = FromLocateResponse(response);
    const LocateResult expected = reference_->Locate(q);
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
  EXPECT_GT(with_value, reference_->dataset().points.size() + 500);
}

TEST_F(LocatordGisTest, GetStatsReportsTheCrs) {
  const v1::GetStatsResponse stats = GetStats(*stub_, kTerrain);
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
  grpc::Status status =
      Reload(*stub_, *gpkg_ + "?layer=nope", &response, kTerrain);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_THAT(status.error_message(),
              HasSubstr(*gpkg_ + ": no layer 'nope' (layers: 'hill')"));

  // The northern half of the hill, assigned UTM zone 32N.
  status = Reload(*stub_,
                  *gpkg_ + "?where=id%20%25%2015%20%3E%3D%207&a_srs=EPSG:32632",
                  &response, kTerrain);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().input_points(), 8u * kHillSide);
  EXPECT_EQ(response.dataset().crs().epsg_code(), 32632u);
  EXPECT_EQ(GetStats(*stub_, kTerrain).dataset().crs().name(),
            "WGS 84 / UTM zone 32N");

  // A generator has no CRS.
  status = Reload(*stub_, "uniform:1000:3", &response, kTerrain);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_FALSE(GetStats(*stub_, kTerrain).dataset().has_crs());
  v1::LocateResponse located;
  grpc::ClientContext context;
  const grpc::Status no_crs =
      stub_->Locate(&context, LonLatRequest({15, 49.65}, false), &located);
  EXPECT_EQ(no_crs.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(no_crs.error_message(),
              HasSubstr("the request names CRS 'EPSG:4326' but the dataset "
                        "has none"));

  // Back to the original for the other tests.
  ASSERT_TRUE(Reload(*stub_, *gpkg_, &response, kTerrain).ok());
  EXPECT_EQ(response.dataset().crs().epsg_code(), 32633u);
}

TEST_F(LocatordGisTest, LonLatRequestsMatchPointsProjectedByCs2cs) {
  const std::vector<Point2> lon_lat = LonLatQueries();
  const std::vector<Point2> utm =
      gis::testing::Cs2cs(lon_lat, "EPSG:4326", "EPSG:32633", dir_->path());
  ASSERT_EQ(utm.size(), lon_lat.size());
  v1::LocateBatchRequest batch = BatchRequestFor(lon_lat);
  batch.set_crs("EPSG:4326");
  batch.set_dataset(kTerrain);
  v1::LocateBatchResponse batch_response;
  {
    grpc::ClientContext context;
    const grpc::Status status =
        stub_->LocateBatch(&context, batch, &batch_response);
    ASSERT_TRUE(status.ok()) << status.error_message();
  }
  size_t inside = 0;
  for (size_t i = 0; i < lon_lat.size(); ++i) {
    v1::LocateResponse in_utm, in_lon_lat;
    ASSERT_TRUE(LocateOne(*stub_, utm[i], &in_utm, kTerrain).ok());
    grpc::ClientContext context;
    const grpc::Status status =
        stub_->Locate(&context, LonLatRequest(lon_lat[i], false), &in_lon_lat);
    ASSERT_TRUE(status.ok()) << status.error_message();
    EXPECT_EQ(in_lon_lat.type(), in_utm.type()) << i;
    EXPECT_EQ(in_lon_lat.triangle_id(), in_utm.triangle_id()) << i;
    EXPECT_THAT(in_lon_lat.vertex_ids(),
                ::testing::ElementsAreArray(in_utm.vertex_ids()));
    EXPECT_EQ(in_lon_lat.has_value(), in_utm.has_value()) << i;
    if (in_utm.has_value()) {
      ++inside;
      EXPECT_NEAR(in_lon_lat.value(), in_utm.value(), 1e-6) << i;
    }
    EXPECT_EQ(batch_response.triangle_ids(static_cast<int>(i)),
              in_utm.triangle_id())
        << i;
  }
  EXPECT_GT(inside, lon_lat.size() / 2);
}

TEST_F(LocatordGisTest, VerticesComeBackInTheRequestCrs) {
  const Point2 q{15.001, 49.651};
  v1::LocateResponse in_dataset_crs, in_lon_lat;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(
        stub_->Locate(&context, LonLatRequest(q, false), &in_dataset_crs).ok());
  }
  grpc::ClientContext context;
  ASSERT_TRUE(
      stub_->Locate(&context, LonLatRequest(q, true), &in_lon_lat).ok());
  std::vector<Point2> utm_vertices;
  for (const v1::Point& v : in_dataset_crs.vertices()) {
    utm_vertices.push_back({v.x(), v.y()});
  }
  const std::vector<Point2> expected = gis::testing::Cs2cs(
      utm_vertices, "EPSG:32633", "EPSG:4326", dir_->path());
  ASSERT_EQ(in_lon_lat.vertices_size(), 3);
  ASSERT_EQ(expected.size(), 3u);
  for (int corner = 0; corner < 3; ++corner) {
    EXPECT_NEAR(in_lon_lat.vertices(corner).x(), expected[corner].x, 1e-9);
    EXPECT_NEAR(in_lon_lat.vertices(corner).y(), expected[corner].y, 1e-9);
  }
}

TEST_F(LocatordGisTest, StreamRequestsCarryTheirCrs) {
  grpc::ClientContext context;
  auto stream = stub_->LocateStream(&context);
  const Point2 q{15.001, 49.651};
  ASSERT_TRUE(stream->Write(LonLatRequest(q, false)));
  v1::LocateRequest plain = LocateRequestFor(
      gis::testing::Cs2cs({q}, "EPSG:4326", "EPSG:32633", dir_->path()).at(0),
      kTerrain);
  ASSERT_TRUE(stream->Write(plain));
  ASSERT_TRUE(stream->WritesDone());
  v1::LocateResponse first, second;
  ASSERT_TRUE(stream->Read(&first));
  ASSERT_TRUE(stream->Read(&second));
  EXPECT_EQ(first.triangle_id(), second.triangle_id());
  EXPECT_NEAR(first.value(), second.value(), 1e-6);
  EXPECT_TRUE(stream->Finish().ok());
}

TEST_F(LocatordGisTest, BadRequestCrssAreInvalidArgument) {
  v1::LocateRequest request = LonLatRequest({15, 49.65}, false);
  request.set_crs("EPSG:999999");
  v1::LocateResponse response;
  {
    grpc::ClientContext context;
    const grpc::Status status = stub_->Locate(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_THAT(status.error_message(), HasSubstr("unknown CRS 'EPSG:999999'"));
  }
  {
    grpc::ClientContext context;
    const grpc::Status status =
        stub_->Locate(&context, LonLatRequest({40, 10}, false), &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_THAT(status.error_message(),
                HasSubstr("point 0 (40, 10) is outside the area of use"));
  }
  v1::LocateBatchRequest batch = BatchRequestFor(
      std::vector<Point2>{{15, 49.65}, {15.01, 49.66}, {-70, 0}});
  batch.set_crs("EPSG:4326");
  batch.set_dataset(kTerrain);
  v1::LocateBatchResponse batch_response;
  grpc::ClientContext context;
  const grpc::Status status =
      stub_->LocateBatch(&context, batch, &batch_response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(status.error_message(), HasSubstr("point 2 (-70, 0)"));
}

// The batch's own checks come before the transform: an oversized batch is
// refused for its size, whatever its CRS, without being transformed.
TEST_F(LocatordGisTest, OversizedBatchIsRefusedBeforeItsCrsIsRead) {
  v1::LocateBatchRequest batch = BatchRequestFor(
      std::vector<Point2>(kMaxBatchPoints + 1, Point2{15, 49.65}));
  batch.set_crs("EPSG:999999");
  batch.set_dataset(kTerrain);
  v1::LocateBatchResponse response;
  grpc::ClientContext context;
  const grpc::Status status = stub_->LocateBatch(&context, batch, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED)
      << status.error_message();
}

// The hill is served beside a second dataset: both are listed, the default
// is the other one (no CRS, so a lon/lat request to it is refused), and
// reloading the hill leaves it untouched.
TEST_F(LocatordGisTest, IsServedBesideASecondDataset) {
  v1::ListDatasetsResponse list;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(
        stub_->ListDatasets(&context, v1::ListDatasetsRequest(), &list).ok());
  }
  ASSERT_EQ(list.datasets_size(), 2);
  EXPECT_EQ(list.datasets(0).name(), "bedrock");
  EXPECT_TRUE(list.datasets(0).is_default());
  EXPECT_EQ(list.datasets(0).stats().source(), kBedrockSpec);
  EXPECT_FALSE(list.datasets(0).stats().has_crs());
  EXPECT_EQ(list.datasets(1).name(), kTerrain);
  EXPECT_FALSE(list.datasets(1).is_default());
  EXPECT_EQ(list.datasets(1).stats().crs().epsg_code(), 32633u);

  v1::LocateRequest to_bedrock = LonLatRequest({15, 49.65}, false);
  to_bedrock.clear_dataset();
  v1::LocateResponse response;
  grpc::ClientContext context;
  const grpc::Status status = stub_->Locate(&context, to_bedrock, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(status.error_message(), HasSubstr("the dataset has none"));

  const uint64_t bedrock_generation = GetStats(*stub_).generation();
  v1::ReloadResponse reloaded;
  ASSERT_TRUE(Reload(*stub_, "", &reloaded, kTerrain).ok());
  EXPECT_EQ(GetStats(*stub_).generation(), bedrock_generation);
  EXPECT_EQ(GetStats(*stub_).dataset().input_points(), 3000u);
}

}  // namespace
}  // namespace locator::test
