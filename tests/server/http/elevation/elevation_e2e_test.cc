// Open Topo Data and OGC API - EDR end to end, against the real locatord
// serving a hill in UTM zone 33N (a GeoPackage made by ogr2ogr) beside a
// generated dataset without a CRS: queried in latitude/longitude with the
// URLs and bodies Open Topo Data's documentation shows, every value equals
// what gRPC's LocateBatch (request CRS EPSG:4326) or Profile gives for the
// same points and lines, null exactly where gRPC has none, and null (not an
// error) outside the CRS's area of use; EDR answers the same in CRS84 and in
// the dataset's own CRS. Every refusal has its status, shape and message,
// and both APIs want the data token when the server has one.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/input_text.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/status_e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

constexpr int kElevationHillSide = 30;  // 900 points, 400 m apart: ~12 km
constexpr char kElevationToken[] = "elevation-token-77";

// Google's Encoded Polyline Algorithm Format, for the test's own requests.
std::string EncodePolyline(const std::vector<Point2>& lng_lat) {
  std::string encoded;
  int64_t previous_lat = 0;
  int64_t previous_lng = 0;
  const auto put = [&encoded](int64_t delta) {
    uint64_t bits = delta < 0 ? ~(static_cast<uint64_t>(delta) << 1)
                              : static_cast<uint64_t>(delta) << 1;
    while (bits >= 0x20) {
      encoded.push_back(static_cast<char>((0x20 | (bits & 0x1f)) + 63));
      bits >>= 5;
    }
    encoded.push_back(static_cast<char>(bits + 63));
  };
  for (const Point2& p : lng_lat) {
    const int64_t lat = std::llround(p.y * 1e5);
    const int64_t lng = std::llround(p.x * 1e5);
    put(lat - previous_lat);
    put(lng - previous_lng);
    previous_lat = lat;
    previous_lng = lng;
  }
  return encoded;
}

// "lat,lng|lat,lng", each number exactly.
std::string LatLngs(const std::vector<Point2>& lng_lat) {
  std::string text;
  for (const Point2& p : lng_lat) {
    if (!text.empty()) text += "|";
    text += NumberText(p.y) + "," + NumberText(p.x);
  }
  return text;
}

// `text` with the characters a URL's query may not carry escaped.
std::string UrlEscaped(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ||
        c == ',' || c == '_') {
      escaped.push_back(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof(hex), "%%%02X", static_cast<unsigned char>(c));
      escaped += hex;
    }
  }
  return escaped;
}

// "x y, x y".
std::string WktPoints(const std::vector<Point2>& points, bool parenthesized) {
  std::string text;
  for (const Point2& p : points) {
    if (!text.empty()) text += ",";
    const std::string pair = NumberText(p.x) + " " + NumberText(p.y);
    text += parenthesized ? "(" + pair + ")" : pair;
  }
  return text;
}

// GETs `target`, a CoverageJSON answer, and parses it; a failure is a test
// failure and yields null.
JsonValue GetCoverage(int port, const std::string& target) {
  HttpReply reply;
  JsonValue coverage;
  EXPECT_TRUE(HttpGet(port, target, &reply).ok());
  EXPECT_EQ(reply.status, 200u) << target << ": " << reply.body;
  EXPECT_EQ(reply.headers["content-type"], "application/prs.coverage+json");
  EXPECT_TRUE(ParseJson(reply.body, &coverage).ok()) << reply.body;
  return coverage;
}

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
ScratchDir* ElevationE2eTest::dir_ = nullptr;
std::unique_ptr<LocatordWithHttp> ElevationE2eTest::server_;

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
