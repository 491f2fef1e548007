// Cesium terrain end to end, against the real locatord serving a hill in
// UTM zone 33N (a GeoPackage made by ogr2ogr) beside a generated dataset
// without a CRS: layer.json, a tile plain and gzipped (the same bytes once
// inflated, each with its own ETag and 304), decoded by the independent
// decoder (node_decoder.h) to heights on the hill, and every refusal with
// its status and message.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tests/server/http/hill_server_test.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/tiles/quantized_mesh/node_decoder.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using Code = grpc::StatusCode;

// The level-11 tile holding the hill's centre, 15°E 49.6525°N: x =
// (15 + 180) / (180 / 2^11), y = (49.6525 + 90) / (180 / 2^11), rounded
// down.
constexpr char kTile[] =
    "/v1/datasets/terrain/quantized-mesh/11/2218/1588.terrain";

// `gzipped` inflated with zlib; empty if it is not gzip.
std::string Gunzip(const std::string& gzipped) {
  z_stream stream{};
  if (inflateInit2(&stream, 15 + 16) != Z_OK) return "";
  std::string out(1 << 22, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(gzipped.data()));
  stream.avail_in = static_cast<uInt>(gzipped.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int result = inflate(&stream, Z_FINISH);
  inflateEnd(&stream);
  if (result != Z_STREAM_END) return "";
  out.resize(stream.total_out);
  return out;
}

class QuantizedMeshE2eTest : public HillServerTest {};

TEST_F(QuantizedMeshE2eTest, LayerJsonDescribesTheTiles) {
  HttpReply reply;
  ASSERT_TRUE(
      HttpGet(port(), "/v1/datasets/terrain/quantized-mesh/layer.json", &reply)
          .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  const JsonValue json =
      GetJson(port(), "/v1/datasets/terrain/quantized-mesh/layer.json");
  EXPECT_EQ(json["tilejson"].string(), "2.1.0");
  EXPECT_EQ(json["format"].string(), "quantized-mesh-1.0");
  EXPECT_EQ(json["scheme"].string(), "tms");
  EXPECT_EQ(json["projection"].string(), "EPSG:4326");
  ASSERT_EQ(json["tiles"].array().size(), 1u);
  EXPECT_EQ(json["tiles"].array()[0].string(),
            "{z}/{x}/{y}.terrain?v={version}");
  EXPECT_THAT(json["version"].string(), HasSubstr("-1-mesh"));
  EXPECT_TRUE(json["extensions"].array().empty());
  const JsonArray& bounds = json["bounds"].array();
  ASSERT_EQ(bounds.size(), 4u);
  EXPECT_LT(bounds[0].number(), 15);
  EXPECT_GT(bounds[2].number(), 15);
  EXPECT_LT(bounds[1].number(), 49.6525);
  EXPECT_GT(bounds[3].number(), 49.6525);
  // 400 m spacing: tiles 64 spacings (25.6 km) wide are level 10's
  // (19.6 km; level 9's are 39 km).
  EXPECT_EQ(json["minzoom"].number(), 0);
  EXPECT_EQ(json["maxzoom"].number(), 10);
  const JsonArray& available = json["available"].array();
  ASSERT_EQ(available.size(), 11u);
  // Level 0: the eastern tile alone; level 10: the tiles round 15°E.
  const JsonValue& zero = available[0].array()[0];
  EXPECT_EQ(zero["startX"].number(), 1);
  EXPECT_EQ(zero["endX"].number(), 1);
  EXPECT_EQ(zero["startY"].number(), 0);
  EXPECT_EQ(zero["endY"].number(), 0);
  const JsonValue& ten = available[10].array()[0];
  EXPECT_EQ(ten["startX"].number(), 1108);  // 14.9414°E..15.1172°E
  EXPECT_EQ(ten["endX"].number(), 1109);
  EXPECT_EQ(ten["startY"].number(), 794);  // 49.5703°N..49.7461°N
  EXPECT_EQ(ten["endY"].number(), 794);
  HttpReply again;
  ASSERT_TRUE(SendHttp(port(), "GET",
                       "/v1/datasets/terrain/quantized-mesh/layer.json", &again,
                       {}, {{"If-None-Match", reply.headers.at("etag")}})
                  .ok());
  EXPECT_EQ(again.status, 304u);
}

TEST_F(QuantizedMeshE2eTest, ATileIsGzippedWhenAskedAndDecodesOnTheHill) {
  HttpReply plain;
  ASSERT_TRUE(SendHttp(port(), "GET", kTile, &plain, {},
                       {{"Accept",
                         "application/vnd.quantized-mesh;"
                         "extensions=octvertexnormals,"
                         "application/octet-stream;q=0.9,*/*;"
                         "q=0.01"}})
                  .ok());
  ASSERT_EQ(plain.status, 200u) << plain.body;
  EXPECT_EQ(plain.headers.at("content-type"), "application/vnd.quantized-mesh");
  EXPECT_EQ(plain.headers.count("content-encoding"), 0u);
  EXPECT_EQ(plain.headers.at("vary"), "Accept-Encoding");
  EXPECT_EQ(plain.headers.at("cache-control"), "public, max-age=60");

  HttpReply gzipped;
  ASSERT_TRUE(SendHttp(port(), "GET", kTile, &gzipped, {},
                       {{"Accept-Encoding", "deflate, gzip;q=0.8"}})
                  .ok());
  ASSERT_EQ(gzipped.status, 200u) << gzipped.body;
  EXPECT_EQ(gzipped.headers.at("content-encoding"), "gzip");
  EXPECT_LT(gzipped.body.size(), plain.body.size());
  EXPECT_TRUE(Gunzip(gzipped.body) == plain.body) << "another tile";
  EXPECT_NE(gzipped.headers.at("etag"), plain.headers.at("etag"));
  HttpReply refused_gzip;
  ASSERT_TRUE(SendHttp(port(), "GET", kTile, &refused_gzip, {},
                       {{"Accept-Encoding", "gzip;q=0"}})
                  .ok());
  EXPECT_EQ(refused_gzip.headers.count("content-encoding"), 0u);

  for (const HttpReply* reply : {&plain, &gzipped}) {
    HttpReply again;
    ASSERT_TRUE(SendHttp(port(), "GET", kTile, &again, {},
                         {{"If-None-Match", reply->headers.at("etag")},
                          {"Accept-Encoding", reply == &gzipped ? "gzip" : ""}})
                    .ok());
    EXPECT_EQ(again.status, 304u);
    EXPECT_TRUE(again.body.empty());
  }

  const std::string file = dir_->path() + "/tile.terrain";
  std::ofstream(file, std::ios::binary) << plain.body;
  std::vector<DecodedTile> decoded;
  const Status read = DecodeWithNode({file}, &decoded);
  ASSERT_TRUE(read.ok()) << read.ToString();
  const DecodedTile& tile = decoded[0];
  // Level 11's geometric error (37.6 m) keeps a few dozen of the hill's
  // vertices.
  EXPECT_GE(tile.vertices.size(), 10u);
  EXPECT_GE(tile.triangles.size(), 10u);
  // The hill's heights (gis_fixtures.h's UtmHill) are 400 m to 700 m.
  EXPECT_GE(tile.min_height, 399);
  EXPECT_LE(tile.max_height, 701);
  EXPECT_LT(tile.min_height, tile.max_height);
}

TEST_F(QuantizedMeshE2eTest, RefusalsArePreciseAndTheServerKeepsServing) {
  struct Row {
    std::string method, target;
    unsigned http;
    Code code;
    std::string message;
    HttpHeaders headers = {};
  };
  const std::string qm = "/v1/datasets/terrain/quantized-mesh/";
  const std::vector<Row> rows = {
      {"GET", qm + "25/0/0.terrain", 400, Code::INVALID_ARGUMENT,
       "tile zoom '25' is not a whole number in 0..24"},
      {"GET", qm + "3/16/0.terrain", 400, Code::INVALID_ARGUMENT,
       "tile x at zoom 3 '16' is not a whole number in 0..15"},
      {"GET", qm + "3/0/8.terrain", 400, Code::INVALID_ARGUMENT,
       "tile y at zoom 3 '8' is not a whole number in 0..7"},
      {"GET", qm + "3/0/-1.terrain", 400, Code::INVALID_ARGUMENT,
       "tile y at zoom 3 '-1'"},
      {"GET", qm + "1/" + std::string(5000, '9') + "/0.terrain", 400,
       Code::INVALID_ARGUMENT, "tile x at zoom 1"},
      {"GET",
       qm + "0/0/0.terrain",
       406,
       Code::INVALID_ARGUMENT,
       "a tile is application/vnd.quantized-mesh, which the request's "
       "Accept does not take",
       {{"Accept", "image/png, application/vnd.quantized-mesh;q=0"}}},
      {"GET", "/v1/datasets/lava/quantized-mesh/0/0/0.terrain", 404,
       Code::NOT_FOUND, "unknown dataset 'lava'"},
      {"GET", "/v1/datasets/plain/quantized-mesh/0/0/0.terrain", 400,
       Code::FAILED_PRECONDITION,
       "dataset 'plain' has no CRS, so its terrain has no place on a web "
       "map's tiles (EPSG:4326)"},
      {"GET", "/v1/datasets/plain/quantized-mesh/layer.json", 400,
       Code::FAILED_PRECONDITION, "dataset 'plain' has no CRS"},
      {"GET", qm + "0/0.terrain", 404, Code::NOT_FOUND, "no API method"},
      {"GET", qm + "0/0/0/0.terrain", 404, Code::NOT_FOUND, "no API method"},
      {"GET", qm + "0/0/0.png", 404, Code::NOT_FOUND, "no API method"},
      {"GET", qm + "tiles.json", 404, Code::NOT_FOUND, "no API method"},
      {"POST", qm + "0/0/0.terrain", 405, Code::UNIMPLEMENTED,
       "'POST' is not allowed"},
      {"DELETE", qm + "layer.json", 405, Code::UNIMPLEMENTED,
       "'DELETE' is not allowed"},
  };
  for (const Row& row : rows) {
    HttpReply reply;
    HttpHeaders headers = row.headers;
    headers.emplace_back("Content-Type", "application/json");
    ASSERT_TRUE(
        SendHttp(port(), row.method, row.target, &reply, "{}", headers).ok())
        << row.target;
    SCOPED_TRACE(row.method + " " + row.target.substr(0, 80));
    ExpectError(reply, row.http, row.code, row.message);
  }
  // The western half of the world has none of the hill: a tile without
  // vertices, not an error.
  HttpReply west;
  ASSERT_TRUE(HttpGet(port(), qm + "0/0/0.terrain", &west).ok());
  ASSERT_EQ(west.status, 200u) << west.body;
  EXPECT_EQ(west.body.size(), 88u + 4 + 4 + 4 * 4);
  HttpReply east;
  ASSERT_TRUE(HttpGet(port(), qm + "0/1/0.terrain", &east).ok());
  ASSERT_EQ(east.status, 200u) << east.body;
  EXPECT_GT(east.body.size(), 200u);
}

}  // namespace
}  // namespace locator::test
