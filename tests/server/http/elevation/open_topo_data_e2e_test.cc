// Open Topo Data end to end (elevation_e2e_support.h has the server):
// queried in latitude/longitude with the URLs and bodies Open Topo Data's
// documentation shows, every value equals what gRPC's LocateBatch (request
// CRS EPSG:4326) or Profile gives for the same points and lines, null
// exactly where gRPC has none, and null (not an error) outside the CRS's
// area of use; several datasets answer in turn. Every refusal has Open Topo
// Data's shape, and both elevation APIs want the data token when the
// server has one.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "common/input_text.h"
#include "tests/server/http/elevation/elevation_e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

TEST_F(ElevationE2eTest, OpenTopoDataGetIsGrpcLocateBatchInLatLng) {
  const std::vector<Point2> points = LngLatGrid(8);
  const std::vector<double> expected = GrpcValues(points, "EPSG:4326");
  HttpReply reply;
  // As Open Topo Data's documentation writes it: '|' and ',' unescaped.
  ASSERT_TRUE(HttpGet(port(),
                      "/opentopodata/v1/terrain?locations=" + LatLngs(points),
                      &reply)
                  .ok());
  ExpectResults(reply, points, expected);

  // The same points as an encoded polyline (rounded to 1e-5 degrees as the
  // format is), with and without "enc:".
  std::vector<Point2> rounded = points;
  for (Point2& p : rounded) {
    p = {std::round(p.x * 1e5) / 1e5, std::round(p.y * 1e5) / 1e5};
  }
  const std::vector<double> rounded_expected =
      GrpcValues(rounded, "EPSG:4326", v1::INTERPOLATION_NEAREST);
  for (const std::string prefix : {"enc:", ""}) {
    ASSERT_TRUE(HttpGet(port(),
                        "/opentopodata/v1/terrain?interpolation=nearest&"
                        "locations=" +
                            UrlEscaped(prefix + EncodePolyline(rounded)),
                        &reply)
                    .ok());
    ExpectResults(reply, rounded, rounded_expected, 1e-12);
  }
}

TEST_F(ElevationE2eTest, OpenTopoDataPostsAreGrpcLocateBatchInLatLng) {
  // More points than a URL holds, in a body large enough to be read in the
  // expensive lane: the JSON body Open Topo Data documents.
  const std::vector<Point2> points = LngLatGrid(45);
  const std::vector<double> expected = GrpcValues(points, "EPSG:4326");
  const HttpReply json = Post(port(), "/opentopodata/v1/terrain",
                              R"({"locations": ")" + LatLngs(points) +
                                  R"(", "interpolation": "bilinear"})");
  ExpectResults(json, points, expected);

  HttpReply form;
  ASSERT_TRUE(SendHttp(port(), "POST", "/opentopodata/v1/terrain", &form,
                       "locations=" + UrlEscaped(LatLngs(points)),
                       {{"Content-Type", "application/x-www-form-urlencoded"}})
                  .ok());
  ExpectResults(form, points, expected);
}

TEST_F(ElevationE2eTest, OpenTopoDataAnswersNullOutsideTheCrsAreaOfUse) {
  // Longitude 10 is outside UTM zone 33N's area of use (12 to 18 degrees
  // east): gRPC refuses the batch, Open Topo Data answers null there.
  std::vector<Point2> points = LngLatGrid(3);
  points.push_back({10, 10});
  v1::LocateBatchRequest request;
  request.set_dataset("terrain");
  request.set_crs("EPSG:4326");
  for (const Point2& p : points) {
    request.add_xs(p.x);
    request.add_ys(p.y);
  }
  v1::LocateBatchResponse response;
  grpc::ClientContext context;
  const grpc::Status refused =
      server_->NewStub()->LocateBatch(&context, request, &response);
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::INVALID_ARGUMENT);

  std::vector<double> expected = GrpcValues(LngLatGrid(3), "EPSG:4326");
  expected.push_back(std::nan(""));
  HttpReply reply;
  ASSERT_TRUE(HttpGet(port(),
                      "/opentopodata/v1/terrain?nodata_value=-9999&locations=" +
                          LatLngs(points),
                      &reply)
                  .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  JsonValue answer;
  ASSERT_TRUE(ParseJson(reply.body, &answer).ok()) << reply.body;
  const JsonArray& results = answer["results"].array();
  ASSERT_EQ(results.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(results[i]["elevation"].number(),
              std::isnan(expected[i]) ? -9999 : expected[i])
        << i;
  }
}

TEST_F(ElevationE2eTest, OpenTopoDataSamplesArePathProfileSamples) {
  std::vector<Point2> utm = {
      {493000, 5493500}, {503000, 5501000}, {507000, 5496000}};
  ASSERT_TRUE(ToLngLat()->ToRequest(utm).ok());
  const v1::ProfileResponse profile = GrpcProfile(utm, "EPSG:4326", 25);
  ASSERT_EQ(profile.samples_size(), 25);
  std::vector<Point2> where;
  std::vector<double> expected;
  for (const v1::ProfilePoint& sample : profile.samples()) {
    where.push_back({sample.point().x(), sample.point().y()});
    expected.push_back(sample.has_value() ? sample.value() : std::nan(""));
  }
  ASSERT_TRUE(ToLngLat()->ToRequest(where).ok());
  for (const std::string& target :
       {"/opentopodata/v1/terrain?samples=25&locations=" + LatLngs(utm),
        "/opentopodata/v1/terrain?samples=25&path=" + LatLngs(utm)}) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port(), target, &reply).ok());
    ExpectResults(reply, where, expected, 1e-9);
  }
}

TEST_F(ElevationE2eTest, OpenTopoDataTakesEachPointFromTheFirstDataset) {
  const std::vector<Point2> points = LngLatGrid(8);
  const std::vector<double> small =
      GrpcValues(points, "EPSG:4326", v1::INTERPOLATION_LINEAR, "small");
  const std::vector<double> terrain = GrpcValues(points, "EPSG:4326");
  HttpReply reply;
  ASSERT_TRUE(
      HttpGet(port(),
              "/opentopodata/v1/small,terrain?locations=" + LatLngs(points),
              &reply)
          .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  JsonValue answer;
  ASSERT_TRUE(ParseJson(reply.body, &answer).ok()) << reply.body;
  const JsonArray& results = answer["results"].array();
  ASSERT_EQ(results.size(), points.size());
  size_t from_small = 0;
  size_t from_terrain = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const JsonValue& result = results[i];
    if (!std::isnan(small[i])) {
      ++from_small;
      EXPECT_EQ(result["elevation"].number(), small[i]) << i;
      EXPECT_EQ(result["dataset"].string(), "small") << i;
    } else if (!std::isnan(terrain[i])) {
      ++from_terrain;
      EXPECT_EQ(result["elevation"].number(), terrain[i]) << i;
      EXPECT_EQ(result["dataset"].string(), "terrain") << i;
    } else {
      EXPECT_TRUE(result["elevation"].is_null()) << i;
      EXPECT_EQ(result["dataset"].string(), "terrain") << i;
    }
  }
  EXPECT_GT(from_small, 0u);
  EXPECT_GT(from_terrain, 0u);
}

TEST_F(ElevationE2eTest, OpenTopoDataRefusesInItsOwnShape) {
  const auto expect = [this](const std::string& target, unsigned http,
                             const std::string& status,
                             const std::string& message) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port(), target, &reply).ok());
    EXPECT_EQ(reply.status, http) << target << ": " << reply.body;
    JsonValue answer;
    ASSERT_TRUE(ParseJson(reply.body, &answer).ok()) << reply.body;
    EXPECT_EQ(answer["status"].string(), status) << target;
    EXPECT_THAT(answer["error"].string(), HasSubstr(message)) << target;
  };
  expect("/opentopodata/v1/terrain?locations=49.6,15&interpolation=cubic", 400,
         "INVALID_REQUEST", "Invalid interpolation method 'cubic'.");
  expect("/opentopodata/v1/lava?locations=49.6,15", 400, "INVALID_REQUEST",
         "unknown dataset 'lava'");
  expect("/opentopodata/v1/plain?locations=49.6,15", 400, "INVALID_REQUEST",
         "has no coordinate reference system");
  expect("/opentopodata/v1/terrain?locations=91,15", 400, "INVALID_REQUEST",
         "Latitude must be between -90 and 90.");
  expect("/opentopodata/v1/terrain?locations=49.6,15&samples=1", 400,
         "INVALID_REQUEST", "at least 2 samples");
  expect("/opentopodata/v1/terrain?locations=49.6,15|49.7,15&samples=100001",
         400, "INVALID_REQUEST", "--max-profile-samples");
  expect("/opentopodata/v1/", 404, "INVALID_REQUEST",
         "No dataset name provided.");
  expect("/opentopodata/v1/small,small?locations=49.6,15", 400,
         "INVALID_REQUEST", "Duplicate dataset names provided.");
  expect("/opentopodata/v1/,,?locations=49.6,15", 400, "INVALID_REQUEST",
         "No valid dataset names provided.");
  expect("/opentopodata/v1/small,plain?locations=49.6,15", 400,
         "INVALID_REQUEST", "Dataset 'plain' has no coordinate reference");
  expect("/opentopodata/v1/terrain/x", 404, "INVALID_REQUEST", "no such path");
}

TEST(ElevationTokenTest, BothApisWantTheDataToken) {
  ScratchDir dir;
  const std::string token_file = dir.path() + "/token";
  std::ofstream(token_file) << kElevationToken << "\n";
  const std::string gpkg = gis::testing::UtmHillGeoPackage(10, dir.path());
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start(gpkg, {"--token-file", token_file},
                                      &server, kElevationToken)
                  .ok());
  const HttpHeaders token = {
      {"Authorization", std::string("Bearer ") + kElevationToken}};
  for (const std::string target :
       {"/opentopodata/v1/default?locations=49.65,15",
        "/edr/collections/default/position?coords=POINT(15%2049.65)",
        "/edr/collections"}) {
    HttpReply refused;
    ASSERT_TRUE(HttpGet(server->http_port(), target, &refused).ok());
    EXPECT_EQ(refused.status, 401u) << target;
    HttpReply answered;
    ASSERT_TRUE(
        SendHttp(server->http_port(), "GET", target, &answered, "", token)
            .ok());
    EXPECT_EQ(answered.status, 200u) << target << ": " << answered.body;
  }
  HttpReply denied;
  ASSERT_TRUE(HttpGet(server->http_port(),
                      "/opentopodata/v1/default?locations=49.65,15", &denied)
                  .ok());
  EXPECT_THAT(denied.body, HasSubstr("\"status\":\"REQUEST_DENIED\""));
}

}  // namespace
}  // namespace locator::test
