// OGC API - EDR end to end (elevation_e2e_support.h has the server):
// positions and trajectories in CRS84 and in the dataset's own CRS equal
// gRPC's LocateBatch and Profile (breakpoints, or samples), null exactly
// where gRPC has none; the metadata documents describe each dataset, and
// every refusal names its problem.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/input_text.h"
#include "tests/server/http/elevation/elevation_e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

TEST_F(ElevationE2eTest, EdrPositionIsGrpcLocateBatchInCrs84AndUtm) {
  const std::vector<Point2> points = LngLatGrid(6);
  const std::vector<double> expected = GrpcValues(points, "EPSG:4326");
  const JsonValue coverage = GetCoverage(
      port(), "/edr/collections/terrain/position?coords=" +
                  UrlEscaped("MULTIPOINT(" + WktPoints(points, true) + ")"));
  EXPECT_EQ(coverage["type"].string(), "Coverage");
  EXPECT_EQ(coverage["domain"]["domainType"].string(), "MultiPoint");
  const JsonArray& tuples =
      coverage["domain"]["axes"]["composite"]["values"].array();
  const JsonArray& values = coverage["ranges"]["elevation"]["values"].array();
  ASSERT_EQ(tuples.size(), points.size());
  ASSERT_EQ(values.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(tuples[i].array()[0].number(), points[i].x);
    EXPECT_EQ(tuples[i].array()[1].number(), points[i].y);
    if (std::isnan(expected[i])) {
      EXPECT_TRUE(values[i].is_null()) << i;
    } else {
      EXPECT_EQ(values[i].number(), expected[i]) << i;
    }
  }

  // The same points in the dataset's own CRS, as GeoJSON.
  std::vector<Point2> utm = points;
  ASSERT_TRUE(ToLngLat()->ToDataset(utm).ok());
  const std::vector<double> utm_expected = GrpcValues(utm, "");
  HttpReply reply;
  ASSERT_TRUE(
      HttpGet(port(),
              "/edr/collections/terrain/position?f=GeoJSON&crs=EPSG:32633&"
              "coords=" +
                  UrlEscaped("MULTIPOINT(" + WktPoints(utm, false) + ")"),
              &reply)
          .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  EXPECT_EQ(reply.headers.at("content-type"), "application/geo+json");
  JsonValue geojson;
  ASSERT_TRUE(ParseJson(reply.body, &geojson).ok());
  const JsonArray& features = geojson["features"].array();
  ASSERT_EQ(features.size(), utm.size());
  for (size_t i = 0; i < utm.size(); ++i) {
    const JsonValue& value = features[i]["properties"]["elevation"];
    if (std::isnan(utm_expected[i])) {
      EXPECT_TRUE(value.is_null()) << i;
    } else {
      EXPECT_EQ(value.number(), utm_expected[i]) << i;
    }
  }

  // One POINT is a Point domain.
  const JsonValue point = GetCoverage(
      port(), "/edr/collections/terrain/position?coords=" +
                  UrlEscaped("POINT(" + WktPoints({points[20]}, false) + ")"));
  EXPECT_EQ(point["domain"]["domainType"].string(), "Point");
  EXPECT_EQ(point["ranges"]["elevation"]["values"].array()[0].number(),
            expected[20]);
}

TEST_F(ElevationE2eTest, EdrTrajectoryIsGrpcProfile) {
  std::vector<Point2> line = {{493000, 5493500}, {503000, 5501000}};
  ASSERT_TRUE(ToLngLat()->ToRequest(line).ok());
  const std::string coords =
      UrlEscaped("LINESTRING(" + WktPoints(line, false) + ")");
  for (const uint32_t samples : {0u, 17u}) {
    const v1::ProfileResponse profile = GrpcProfile(line, "EPSG:4326", samples);
    const auto& expected =
        samples > 0 ? profile.samples() : profile.breakpoints();
    ASSERT_GT(expected.size(), 2);
    std::vector<Point2> where;
    for (const v1::ProfilePoint& p : expected) {
      where.push_back({p.point().x(), p.point().y()});
    }
    ASSERT_TRUE(ToLngLat()->ToRequest(where).ok());
    const JsonValue coverage = GetCoverage(
        port(), "/edr/collections/terrain/trajectory?coords=" + coords +
                    (samples > 0 ? "&samples=" + std::to_string(samples) : ""));
    EXPECT_EQ(coverage["domain"]["domainType"].string(), "Trajectory");
    const JsonArray& tuples =
        coverage["domain"]["axes"]["composite"]["values"].array();
    const JsonArray& values = coverage["ranges"]["elevation"]["values"].array();
    ASSERT_EQ(values.size(), static_cast<size_t>(expected.size()));
    ASSERT_EQ(tuples.size(), values.size());
    size_t nulls = 0;
    for (int i = 0; i < expected.size(); ++i) {
      EXPECT_NEAR(tuples[i].array()[0].number(), where[i].x, 1e-9) << i;
      EXPECT_NEAR(tuples[i].array()[1].number(), where[i].y, 1e-9) << i;
      if (expected[i].has_value()) {
        EXPECT_EQ(values[i].number(), expected[i].value()) << i;
      } else {
        EXPECT_TRUE(values[i].is_null()) << i;
        ++nulls;
      }
    }
    // The line starts outside the hull.
    EXPECT_GT(nulls, 0u) << samples;
  }
}

TEST_F(ElevationE2eTest, EdrMetadataDescribesEachDataset) {
  const JsonValue landing = GetJson(port(), "/edr/");
  EXPECT_EQ(landing["links"].array().size(), 3u);
  const JsonValue conformance = GetJson(port(), "/edr/conformance");
  EXPECT_THAT(conformance["conformsTo"].array()[0].string(),
              HasSubstr("ogcapi-edr-1/1.0/conf/core"));

  const JsonValue terrain = GetJson(port(), "/edr/collections/terrain");
  EXPECT_EQ(terrain["id"].string(), "terrain");
  const JsonArray& crs = terrain["crs"].array();
  ASSERT_EQ(crs.size(), 3u);
  EXPECT_EQ(crs[0].string(), "http://www.opengis.net/def/crs/OGC/1.3/CRS84");
  EXPECT_EQ(crs[1].string(), "http://www.opengis.net/def/crs/EPSG/0/32633");
  // The hill is around 15 E, 49.65 N.
  const JsonArray& box =
      terrain["extent"]["spatial"]["bbox"].array()[0].array();
  EXPECT_NEAR(box[0].number(), 14.92, 0.01);
  EXPECT_NEAR(box[1].number(), 49.60, 0.01);
  EXPECT_NEAR(box[2].number(), 15.08, 0.01);
  EXPECT_NEAR(box[3].number(), 49.70, 0.01);
  EXPECT_EQ(terrain["data_queries"]["position"]["link"]["href"].string(),
            "/edr/collections/terrain/position");
  EXPECT_EQ(terrain["parameter_names"]["elevation"]["type"].string(),
            "Parameter");

  const JsonValue collections = GetJson(port(), "/edr/collections");
  ASSERT_EQ(collections["collections"].array().size(), 3u);
  const JsonValue& plain = collections["collections"].array()[1];
  EXPECT_EQ(plain["id"].string(), "plain");
  ASSERT_EQ(plain["crs"].array().size(), 1u);
  EXPECT_EQ(plain["crs"].array()[0].string(), "dataset");
}

TEST_F(ElevationE2eTest, EdrRefusesNamingTheProblem) {
  const auto expect = [this](const std::string& target, unsigned http,
                             const std::string& message) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port(), target, &reply).ok());
    EXPECT_EQ(reply.status, http) << target << ": " << reply.body;
    EXPECT_THAT(reply.body, HasSubstr(message)) << target;
  };
  const std::string position = "/edr/collections/terrain/position?coords=";
  expect(position + "POINT(NaN%2049)", 400, "'NaN' is not a finite number");
  expect(position + "POINT(1e300%2049)", 400,
         "is not a longitude in [-180, 180]");
  expect(position + "POINT(15%2049)&crs=EPSG:4326", 400,
         "is not a CRS of this collection");
  expect(position + "POINT(15%2049)&f=CSV", 400, "unsupported output format");
  expect(position + "LINESTRING(15%2049,16%2049)", 400,
         "a LINESTRING is a trajectory query's");
  expect(position + "POINT(15%2049)&parameter-name=temperature", 400,
         "its one parameter is elevation");
  expect("/edr/collections/terrain/position", 400, "coords is required");
  expect("/edr/collections/terrain/trajectory?coords=POINT(15%2049)", 400,
         "takes a LINESTRING");
  expect(
      "/edr/collections/terrain/trajectory?coords=LINESTRING(15%2049,"
      "15.01%2049.1)&samples=1",
      400, "samples");
  expect("/edr/collections/plain/position?coords=POINT(1%201)&crs=CRS84", 400,
         "it offers dataset");
  expect("/edr/collections/lava", 404, "unknown dataset 'lava'");
  expect("/edr/collections/terrain/area", 404, "no EDR resource");
  HttpReply post;
  ASSERT_TRUE(SendHttp(port(), "POST", "/edr/collections", &post).ok());
  EXPECT_EQ(post.status, 405u);
}

}  // namespace
}  // namespace locator::test
