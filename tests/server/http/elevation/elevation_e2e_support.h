// What the end-to-end tests of the elevation APIs (Open Topo Data and OGC
// API - EDR) share: the server they query (the real locatord serving a hill
// in UTM zone 33N, a GeoPackage made by ogr2ogr, beside a smaller hill over
// its middle and a generated dataset without a CRS), gRPC's answers to
// compare with, and the encodings their requests use.

#ifndef LOCATOR_TESTS_SERVER_HTTP_ELEVATION_ELEVATION_E2E_SUPPORT_H_
#define LOCATOR_TESTS_SERVER_HTTP_ELEVATION_ELEVATION_E2E_SUPPORT_H_

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/status_e2e_support.h"

namespace locator::test {

inline constexpr int kElevationHillSide = 30;  // 900 points, 400 m apart
inline constexpr char kElevationToken[] = "elevation-token-77";

// Google's Encoded Polyline Algorithm Format, for the tests' own requests.
std::string EncodePolyline(const std::vector<Point2>& lng_lat);

// "lat,lng|lat,lng", each number exactly.
std::string LatLngs(const std::vector<Point2>& lng_lat);

// `text` with the characters a URL's query may not carry escaped.
std::string UrlEscaped(const std::string& text);

// "x y, x y" (each pair in parentheses if `parenthesized`).
std::string WktPoints(const std::vector<Point2>& points, bool parenthesized);

// GETs `target`, a CoverageJSON answer, and parses it; a failure is a test
// failure and yields null.
JsonValue GetCoverage(int port, const std::string& target);

class ElevationE2eTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir();
    const std::string gpkg =
        gis::testing::UtmHillGeoPackage(kElevationHillSide, dir_->path());
    // A smaller hill (4 km across) over the same middle, for the
    // multi-dataset requests.
    std::filesystem::create_directory(dir_->path() + "/small");
    const std::string small_gpkg =
        gis::testing::UtmHillGeoPackage(10, dir_->path() + "/small");
    const Status started =
        LocatordWithHttp::Start("terrain=" + gpkg,
                                {"--dataset", "plain=uniform:3000:5",
                                 "--dataset", "small=" + small_gpkg},
                                &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
    ASSERT_TRUE(server_->WaitUntilServes("plain").ok());
    ASSERT_TRUE(server_->WaitUntilServes("small").ok());
  }
  static void TearDownTestSuite() {
    server_.reset();
    delete dir_;
  }
  int port() const { return server_->http_port(); }

  // A grid of `side` x `side` latitude/longitude points over the hill and
  // around it: some inside the hull, some outside.
  static std::vector<Point2> LngLatGrid(int side) {
    std::vector<Point2> utm;
    for (int i = 0; i < side; ++i) {
      for (int j = 0; j < side; ++j) {
        utm.push_back({492000 + 16000.0 * i / (side - 1) + 0.37 * j,
                       5492000 + 16000.0 * j / (side - 1) + 0.21 * i});
      }
    }
    EXPECT_TRUE(ToLngLat()->ToRequest(utm).ok());
    return utm;
  }
  static std::unique_ptr<gis::CrsTransformer> ToLngLat() {
    StatusOr<std::unique_ptr<gis::CrsTransformer>> transformer =
        gis::CrsTransformer::Create("EPSG:4326", "EPSG:32633");
    EXPECT_TRUE(transformer.ok()) << transformer.status().ToString();
    return *std::move(transformer);
  }

  // gRPC LocateBatch's values at `points` in `crs`.
  std::vector<double> GrpcValues(
      const std::vector<Point2>& points, const std::string& crs,
      v1::Interpolation interpolation = v1::INTERPOLATION_LINEAR,
      const std::string& dataset = "terrain") const {
    v1::LocateBatchRequest request;
    request.set_dataset(dataset);
    request.set_crs(crs);
    request.set_include_values(true);
    request.set_interpolation(interpolation);
    for (const Point2& p : points) {
      request.add_xs(p.x);
      request.add_ys(p.y);
    }
    v1::LocateBatchResponse response;
    grpc::ClientContext context;
    const grpc::Status status =
        server_->NewStub()->LocateBatch(&context, request, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return {response.values().begin(), response.values().end()};
  }
  v1::ProfileResponse GrpcProfile(const std::vector<Point2>& line,
                                  const std::string& crs,
                                  uint32_t samples) const {
    v1::ProfileRequest request;
    request.set_dataset("terrain");
    request.set_crs(crs);
    request.set_samples(samples);
    for (const Point2& p : line) {
      v1::Point* vertex = request.add_vertices();
      vertex->set_x(p.x);
      vertex->set_y(p.y);
    }
    v1::ProfileResponse response;
    grpc::ClientContext context;
    const grpc::Status status =
        server_->NewStub()->Profile(&context, request, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return response;
  }

  // Checks an Open Topo Data answer: one result per point, at `where`,
  // with `expected` (null where NaN).
  static void ExpectResults(const HttpReply& reply,
                            const std::vector<Point2>& where,
                            const std::vector<double>& expected,
                            double location_tolerance = 0) {
    ASSERT_EQ(reply.status, 200u) << reply.body.substr(0, 500);
    EXPECT_EQ(reply.headers.at("content-type"), "application/json");
    JsonValue answer;
    ASSERT_TRUE(ParseJson(reply.body, &answer).ok()) << reply.body;
    EXPECT_EQ(answer["status"].string(), "OK");
    const JsonArray& results = answer["results"].array();
    ASSERT_EQ(results.size(), where.size());
    ASSERT_EQ(expected.size(), where.size());
    size_t nulls = 0;
    for (size_t i = 0; i < results.size(); ++i) {
      const JsonValue& result = results[i];
      EXPECT_EQ(result["dataset"].string(), "terrain");
      EXPECT_NEAR(result["location"]["lat"].number(), where[i].y,
                  location_tolerance)
          << i;
      EXPECT_NEAR(result["location"]["lng"].number(), where[i].x,
                  location_tolerance)
          << i;
      if (std::isnan(expected[i])) {
        EXPECT_TRUE(result["elevation"].is_null()) << i;
        ++nulls;
      } else {
        ASSERT_FALSE(result["elevation"].is_null()) << i;
        EXPECT_EQ(result["elevation"].number(), expected[i]) << i;
      }
    }
    EXPECT_GT(nulls, 0u);
    EXPECT_LT(nulls, results.size());
  }

  static ScratchDir* dir_;
  static std::unique_ptr<LocatordWithHttp> server_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_ELEVATION_ELEVATION_E2E_SUPPORT_H_
