// The elevation APIs' parsers with the inputs their specifications show
// and with hostile ones: Google's encoded polylines, Open Topo Data's
// fields (query strings, forms and JSON bodies), EDR's WKT coords, f= and
// crs=.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "server/http/edr/edr_parameters.h"
#include "server/http/edr/wkt_coordinates.h"
#include "server/http/elevation/request_fields.h"
#include "server/http/opentopodata/encoded_polyline.h"
#include "server/http/opentopodata/open_topo_data_query.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

StatusOr<OpenTopoDataQuery> QueryOf(const std::string& query_string) {
  StatusOr<RequestFields> fields = RequestFields::OfForm(query_string);
  if (!fields.ok()) return fields.status();
  return ParseOpenTopoDataQuery(*fields);
}

TEST(EncodedPolylineTest, DecodesGooglesExample) {
  // The example of Google's Encoded Polyline Algorithm Format page.
  const StatusOr<std::vector<Point2>> points =
      DecodePolyline("_p~iF~ps|U_ulLnnqC_mqNvxq`@");
  ASSERT_TRUE(points.ok()) << points.status().ToString();
  ASSERT_EQ(points->size(), 3u);
  EXPECT_DOUBLE_EQ((*points)[0].y, 38.5);
  EXPECT_DOUBLE_EQ((*points)[0].x, -120.2);
  EXPECT_DOUBLE_EQ((*points)[1].y, 40.7);
  EXPECT_DOUBLE_EQ((*points)[1].x, -120.95);
  EXPECT_DOUBLE_EQ((*points)[2].y, 43.252);
  EXPECT_DOUBLE_EQ((*points)[2].x, -126.453);
}

TEST(EncodedPolylineTest, RefusesWhatIsNotAPolyline) {
  for (const auto& [text, problem] :
       std::vector<std::pair<std::string, std::string>>{
           {"_p~iF", "has no longitude"},
           {"_p~i", "unfinished"},
           {"_p~iF~ps|U_", "unfinished"},
           {"_p iF~ps|U", "not a polyline character"},
           {std::string("_p\0iF", 5), "not a polyline character"},
           {"\x80\x81", "not a polyline character"},
           {"~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~?", "more than 7 chunks"},
           // Latitude 1000: 100000000 * 2 in chunks.
           {"_c`|y@?", "outside [-90, 90]"},
       }) {
    const StatusOr<std::vector<Point2>> points = DecodePolyline(text);
    ASSERT_FALSE(points.ok()) << text;
    EXPECT_THAT(points.status().message(), HasSubstr(problem)) << text;
  }
}

TEST(RequestFieldsTest, PercentDecodesStrictly) {
  StatusOr<RequestFields> fields =
      RequestFields::OfForm("locations=1%2C2%7C3,4&a+b=c+d&empty=&flag");
  ASSERT_TRUE(fields.ok()) << fields.status().ToString();
  EXPECT_EQ(fields->Get("locations"), "1,2|3,4");
  EXPECT_EQ(fields->Get("a b"), "c d");
  EXPECT_EQ(fields->Get("empty"), "");
  EXPECT_EQ(fields->Get("flag"), "");
  EXPECT_EQ(fields->Get("absent"), std::nullopt);
  for (const std::string bad : {"a=%", "a=%2", "a=%zz", "a=%00", "%=1"}) {
    const StatusOr<RequestFields> refused = RequestFields::OfForm(bad);
    EXPECT_FALSE(refused.ok()) << bad;
  }
}

HttpRequest Post(std::string content_type, std::string body) {
  HttpRequest request;
  request.method = "POST";
  request.path = "/opentopodata/v1/x";
  request.query = "locations=ignored";
  request.headers = {{"content-type", std::move(content_type)}};
  request.body = std::move(body);
  return request;
}

TEST(RequestFieldsTest, ReadsPostBodiesAsOpenTopoDataDoes) {
  // Open Topo Data's documented POST body.
  StatusOr<RequestFields> json = RequestFields::Of(
      Post("application/json; charset=utf-8",
           R"({"locations": "-43.5,172.5|27.6,1.98", "samples": 5,
               "nodata_value": -9999})"));
  ASSERT_TRUE(json.ok()) << json.status().ToString();
  EXPECT_EQ(json->Get("locations"), "-43.5,172.5|27.6,1.98");
  EXPECT_EQ(json->Get("samples"), "5");
  EXPECT_EQ(json->Get("nodata_value"), "-9999");
  StatusOr<RequestFields> form =
      RequestFields::Of(Post("application/x-www-form-urlencoded",
                             "locations=-43.5,172.5%7C27.6,1.98"));
  ASSERT_TRUE(form.ok()) << form.status().ToString();
  EXPECT_EQ(form->Get("locations"), "-43.5,172.5|27.6,1.98");

  for (const auto& [type, body, problem] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"text/plain", "locations=1,2", "Content-Type"},
           {"application/json", "[1, 2]", "Invalid JSON"},
           {"application/json", "{\"locations\": [[1, 2]]}",
            "strings or numbers"},
           {"application/json", "{\"locations\": \"1,2\"", "Invalid JSON"},
           {"application/json", std::string(200, '[') + std::string(200, ']'),
            "Invalid JSON"},
           // Deep enough to overflow the stack of a recursive parser.
           {"application/json",
            "{\"locations\":" + std::string(100000, '[') +
                std::string(100000, ']') + "}",
            "nests deeper"},
       }) {
    const StatusOr<RequestFields> refused = RequestFields::Of(Post(type, body));
    ASSERT_FALSE(refused.ok()) << body.substr(0, 80);
    EXPECT_THAT(refused.status().message(), HasSubstr(problem))
        << body.substr(0, 80);
  }
  // Brackets and escaped quotes inside strings do not nest.
  const StatusOr<RequestFields> strings = RequestFields::Of(
      Post("application/json", R"({"a": "[[[[", "b": "\"{{", "c": "]]"})"));
  ASSERT_TRUE(strings.ok()) << strings.status().ToString();
  EXPECT_EQ(strings->Get("b"), "\"{{");
}

TEST(OpenTopoDataQueryTest, ReadsOpenTopoDatasDocumentedQueries) {
  StatusOr<OpenTopoDataQuery> query =
      QueryOf("locations=57.688709,11.976404|-43.5,172.5|");
  ASSERT_TRUE(query.ok()) << query.status().ToString();
  ASSERT_EQ(query->points.size(), 2u);
  EXPECT_EQ(query->points[0].x, 11.976404);
  EXPECT_EQ(query->points[0].y, 57.688709);
  EXPECT_EQ(query->interpolation, v1::INTERPOLATION_LINEAR);
  EXPECT_EQ(std::get<OpenTopoDataQuery::NoData>(query->nodata),
            OpenTopoDataQuery::NoData::kNull);

  query = QueryOf("locations=enc:gfo%7DEtohhU&interpolation=nearest");
  ASSERT_TRUE(query.ok()) << query.status().ToString();
  ASSERT_EQ(query->points.size(), 1u);
  EXPECT_DOUBLE_EQ(query->points[0].y, 36.45556);
  EXPECT_EQ(query->interpolation, v1::INTERPOLATION_NEAREST);
  // Without "enc:" too, as Open Topo Data: a text without a comma.
  query = QueryOf("locations=gfo%7DEtohhU");
  ASSERT_TRUE(query.ok()) << query.status().ToString();
  EXPECT_EQ(query->points.size(), 1u);

  query = QueryOf(
      "path=-43.5,172.5|27.6,1.98&samples=5&nodata_value=-9999&"
      "interpolation=natural");
  ASSERT_TRUE(query.ok()) << query.status().ToString();
  EXPECT_EQ(query->samples, 5u);
  EXPECT_EQ(std::get<int64_t>(query->nodata), -9999);
  EXPECT_EQ(query->interpolation, v1::INTERPOLATION_NATURAL_NEIGHBOR);
  query = QueryOf("locations=1,2&nodata_value=NaN&interpolation=bilinear");
  ASSERT_TRUE(query.ok()) << query.status().ToString();
  EXPECT_EQ(std::get<OpenTopoDataQuery::NoData>(query->nodata),
            OpenTopoDataQuery::NoData::kNan);
}

TEST(OpenTopoDataQueryTest, RefusesWithOpenTopoDatasMessages) {
  for (const auto& [text, problem] :
       std::vector<std::pair<std::string, std::string>>{
           {"", "No locations provided."},
           {"locations=", "No locations provided."},
           {"locations=1,2&interpolation=cubic",
            "Invalid interpolation method 'cubic'."},
           {"locations=1,2&interpolation=%00", "NUL"},
           {"locations=1,2|3", "location '3' in position 2."},
           {"locations=1,x", "location '1,x' in position 1."},
           {"locations=nan,1", "Latitude must be between -90 and 90."},
           {"locations=1,inf", "Longitude must be between -180 and 180."},
           {"locations=1e300,1", "Latitude must be between -90 and 90."},
           {"locations=1,-180.0000001", "Longitude must be between"},
           {"locations=4.9e-324,1,2", "location '4.9e-324,1,2'"},
           {"locations=1,2&samples=1", "at least 2 samples"},
           {"locations=1,2&samples=2.5", "Samples should be an integer."},
           {"locations=1,2&samples=99999999999999999999999",
            "Samples should be an integer."},
           {"locations=1,2&nodata_value=1.5", "Invalid nodata value"},
           {"locations=1,2&nodata_value=99999999999999999999",
            "Invalid nodata value"},
           {"path=1,2|3,4", "A path needs samples"},
           {"locations=1,2&path=1,2&samples=2", "not both"},
           {"locations=enc:_p~iF", "has no longitude"},
       }) {
    const StatusOr<OpenTopoDataQuery> query = QueryOf(text);
    ASSERT_FALSE(query.ok()) << text;
    EXPECT_EQ(query.status().code(), Status::Code::kInvalidArgument) << text;
    EXPECT_THAT(query.status().message(), HasSubstr(problem)) << text;
  }
}

TEST(WktCoordinatesTest, ReadsEdrsGeometries) {
  StatusOr<WktCoordinates> point = ParseWktCoordinates("POINT(15 49.65)", 10);
  ASSERT_TRUE(point.ok()) << point.status().ToString();
  EXPECT_EQ(point->type, WktCoordinates::Type::kPoint);
  ASSERT_EQ(point->points.size(), 1u);
  EXPECT_EQ(point->points[0].x, 15);
  EXPECT_EQ(point->points[0].y, 49.65);

  for (const std::string multi :
       {"MULTIPOINT((1 2),(3 4))", "multipoint ( 1 2 , 3 4 )",
        " MultiPoint\t( (1 2) ,(3   4) ) "}) {
    StatusOr<WktCoordinates> parsed = ParseWktCoordinates(multi, 10);
    ASSERT_TRUE(parsed.ok()) << multi << ": " << parsed.status().ToString();
    EXPECT_EQ(parsed->type, WktCoordinates::Type::kMultiPoint);
    ASSERT_EQ(parsed->points.size(), 2u) << multi;
    EXPECT_EQ(parsed->points[1].x, 3);
    EXPECT_EQ(parsed->points[1].y, 4);
  }
  StatusOr<WktCoordinates> line =
      ParseWktCoordinates("LINESTRING(-1.5e2 +2, 3 -4e-3, 5 6)", 10);
  ASSERT_TRUE(line.ok()) << line.status().ToString();
  EXPECT_EQ(line->type, WktCoordinates::Type::kLineString);
  ASSERT_EQ(line->points.size(), 3u);
  EXPECT_EQ(line->points[0].x, -150);
  EXPECT_EQ(line->points[1].y, -4e-3);
}

TEST(WktCoordinatesTest, RefusesHostileWktNamingTheProblem) {
  for (const auto& [text, problem] :
       std::vector<std::pair<std::string, std::string>>{
           {"", "expected POINT, MULTIPOINT or LINESTRING"},
           {"POLYGON((0 0,1 0,1 1,0 0))", "unsupported geometry 'POLYGON'"},
           {"GEOMETRYCOLLECTION(POINT(1 2))", "unsupported geometry"},
           {"POINT EMPTY", "EMPTY"},
           {"POINT Z (1 2 3)", "only 2D"},
           {"POINTM(1 2 3)", "unsupported geometry 'POINTM'"},
           {"POINT(1 2 3)", "two coordinates"},
           {"POINT(1)", "expected a coordinate"},
           {"POINT(NaN 2)", "'NaN' is not a finite number"},
           {"POINT(1 inf)", "'inf' is not a finite number"},
           {"POINT(1 1e999)", "'1e999' is not a finite number"},
           {"POINT(1 2", "expected ')'"},
           {"POINT(1 2))", "text after the geometry"},
           {"POINT(1 2),", "text after the geometry"},
           {"POINT(1 2, 3 4)", "expected ')'"},
           {"POINT(0x10 2)", "'0x10' is not a number"},
           {"LINESTRING(1 2)", "at least 2 points"},
           {"LINESTRING(1 2,,3 4)", "expected a coordinate"},
           {"MULTIPOINT((1 2),3 4)", "expected '('"},
           {"MULTIPOINT(((1 2)))", "expected a coordinate"},
           {std::string(100000, '('), "expected POINT"},
           {"POINT(" + std::string(100000, '1') + " 2)", "not a finite"},
           {"LINESTRING(1 2, 3 4, 5 6, 7 8)", "more than 3 points"},
           {std::string("POINT(1\0 2)", 11), "is not a number"},
       }) {
    const StatusOr<WktCoordinates> parsed = ParseWktCoordinates(text, 3);
    ASSERT_FALSE(parsed.ok()) << text.substr(0, 80);
    EXPECT_EQ(parsed.status().code(), Status::Code::kInvalidArgument);
    EXPECT_THAT(parsed.status().message(), HasSubstr(problem))
        << text.substr(0, 80);
    EXPECT_LT(parsed.status().message().size(), 400u);
  }
}

v1::DatasetStats UtmStats() {
  v1::DatasetStats stats;
  stats.mutable_crs()->set_name("WGS 84 / UTM zone 33N");
  stats.mutable_crs()->set_epsg_code(32633);
  stats.mutable_crs()->add_axis_units("metre");
  stats.mutable_crs()->add_axis_units("metre");
  stats.mutable_crs()->set_wkt("PROJCRS[...]");
  return stats;
}

TEST(EdrParametersTest, FormatsAndCrsOfACollection) {
  EXPECT_EQ(*ParseEdrFormat(std::nullopt), EdrFormat::kCoverageJson);
  EXPECT_EQ(*ParseEdrFormat("CoverageJSON"), EdrFormat::kCoverageJson);
  EXPECT_EQ(*ParseEdrFormat("geojson"), EdrFormat::kGeoJson);
  for (const std::string bad : {"", "json", "GeoJSON ", "CSV"}) {
    const StatusOr<EdrFormat> format = ParseEdrFormat(bad);
    ASSERT_FALSE(format.ok()) << bad;
    EXPECT_THAT(format.status().message(), HasSubstr("CoverageJSON"));
  }

  const std::vector<EdrCrs> offered = OfferedCrs(UtmStats());
  ASSERT_EQ(offered.size(), 3u);
  EXPECT_EQ(offered[0].uri, kCrs84Uri);
  for (const std::string crs84 :
       {"CRS84", "ogc:crs84", "http://www.opengis.net/def/crs/OGC/1.3/CRS84"}) {
    const StatusOr<EdrCrs> crs = ParseEdrCrs(crs84, offered);
    ASSERT_TRUE(crs.ok()) << crs84;
    EXPECT_TRUE(crs->lon_lat);
    EXPECT_EQ(crs->request_crs, "EPSG:4326");
  }
  for (const std::string own :
       {"EPSG:32633", "http://www.opengis.net/def/crs/EPSG/0/32633",
        "dataset"}) {
    const StatusOr<EdrCrs> crs = ParseEdrCrs(own, offered);
    ASSERT_TRUE(crs.ok()) << own;
    EXPECT_FALSE(crs->lon_lat);
    EXPECT_EQ(crs->request_crs, "");
  }
  EXPECT_EQ(ParseEdrCrs(std::nullopt, offered)->uri, kCrs84Uri);
  for (const std::string& bad : std::vector<std::string>{
           "EPSG:4326", "EPSG:", "+proj=longlat", std::string(5000, 'x'),
           "/etc/passwd", "EPSG:32633 "}) {
    const StatusOr<EdrCrs> crs = ParseEdrCrs(bad, offered);
    ASSERT_FALSE(crs.ok()) << bad.substr(0, 80);
    EXPECT_THAT(crs.status().message(), HasSubstr("EPSG/0/32633"));
    EXPECT_LT(crs.status().message().size(), 400u);
  }

  // A dataset without a CRS offers only its own coordinates.
  const std::vector<EdrCrs> plain = OfferedCrs(v1::DatasetStats());
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_EQ(plain[0].uri, kDatasetCrsName);
  EXPECT_FALSE(ParseEdrCrs("CRS84", plain).ok());
}

}  // namespace
}  // namespace locator
