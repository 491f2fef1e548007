// Terrain tiles end to end, against the real locatord serving a hill in
// UTM zone 33N (a GeoPackage made by ogr2ogr) as its default dataset,
// beside a generated dataset without a CRS: every pixel of a tile decodes
// (with libpng) to the value gRPC's LocateBatch gives at the pixel's
// centre, transformed from EPSG:3857 by the test's own PROJ transformer,
// within half the encoding's quantum (a quantum and a half on an edge),
// and is transparent exactly where LocateBatch finds no value. ETags and
// 304s, TileJSON, and every refusal with its status and message; with a
// data token, a tile wants it and is private to caches.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "server/tiles/hillshade.h"
#include "server/tiles/terrain_encoding.h"
#include "server/tiles/tile_address.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/hill_server_test.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/tiles/png_decode.h"
#include "tests/server/tiles/tile_test_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using Code = grpc::StatusCode;

// Its tiles at zoom 12 are ~6 km of ground at the hill's latitude.
constexpr uint32_t kZoom = 12;

std::string TilePath(const TileAddress& t, const std::string& encoding = "",
                     const std::string& dataset = "terrain") {
  return "/v1/datasets/" + dataset + "/tiles/" + std::to_string(t.z) + "/" +
         std::to_string(t.x) + "/" + std::to_string(t.y) + ".png" +
         (encoding.empty() ? "" : "?encoding=" + encoding);
}

class TilesE2eTest : public HillServerTest {
 protected:
  // The zoom-kZoom tile holding the hill's south-west corner (the hill's
  // first point), so that it is partly over the data.
  static TileAddress CornerTile() {
    const std::unique_ptr<gis::CrsTransformer> to_mercator =
        MercatorUtmTransformer();
    std::vector<Point2> corner = {{1e300, 1e300}};
    for (const gis::testing::PointZ& p : gis::testing::UtmHill(kHillSide)) {
      corner[0] = Point2{std::min(corner[0].x, p.x + 100),
                         std::min(corner[0].y, p.y + 100)};
    }
    EXPECT_TRUE(to_mercator->ToRequest(corner).ok());
    const double side = 2 * TileAddress::kHalfWorld / std::ldexp(1.0, kZoom);
    return TileAddress{
        kZoom,
        static_cast<uint32_t>((corner[0].x + TileAddress::kHalfWorld) / side),
        static_cast<uint32_t>((TileAddress::kHalfWorld - corner[0].y) / side)};
  }
};

TEST_F(TilesE2eTest, PixelsAreGrpcLocateBatchValuesAtTheirCentres) {
  const TileAddress tile = CornerTile();
  // The pixel centres from the scheme's definition, in the dataset's CRS.
  const std::vector<Point2> centres = PixelCentresInUtm33(tile);
  ASSERT_EQ(centres.size(), 256u * 256u);
  std::unique_ptr<v1::Locator::Stub> stub = server_->NewStub();
  const std::vector<LocateResult> located =
      LocateInBatches(*stub, centres, 8192);
  ASSERT_EQ(located.size(), centres.size());

  for (const TerrainEncoding encoding :
       {TerrainEncoding::kTerrarium, TerrainEncoding::kMapbox}) {
    const std::string name(TerrainEncodingName(encoding));
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port(), TilePath(tile, name), &reply).ok());
    ASSERT_EQ(reply.status, 200u) << reply.body;
    EXPECT_EQ(reply.headers.at("content-type"), "image/png");
    RgbaImage image;
    const Status decoded = DecodeRgbaPng(reply.body, &image);
    ASSERT_TRUE(decoded.ok()) << decoded.ToString();
    ASSERT_EQ(image.width, 256u);
    ASSERT_EQ(image.height, 256u);
    const double q = TerrainQuantum(encoding);
    size_t opaque = 0;
    for (size_t i = 0; i < centres.size(); ++i) {
      const LocateResult& r = located[i];
      ASSERT_EQ(image.Alpha(i), r.has_value ? 255 : 0)
          << name << " pixel " << i % 256 << "," << i / 256;
      if (!r.has_value) continue;
      ++opaque;
      const bool on_edge =
          r.type == LocationType::kEdge || r.type == LocationType::kVertex;
      ASSERT_NEAR(DecodeHeight(encoding, image.Rgb(i)), r.value,
                  (on_edge ? 1.5 : 0.5) * q + 1e-9)
          << name << " pixel " << i % 256 << "," << i / 256;
    }
    EXPECT_GT(opaque, 1000u) << name;
    EXPECT_LT(opaque, centres.size()) << name;
  }
}

// The hillshade of the same tile: opaque exactly where the terrain has a
// value (gRPC's LocateBatch at the pixel centres), lit as the facet there
// is under the light asked for, its own ETag per light.
TEST_F(TilesE2eTest, HillshadeShadesTheFacetsGrpcFinds) {
  const TileAddress tile = CornerTile();
  const std::vector<Point2> centres = PixelCentresInUtm33(tile);
  std::unique_ptr<v1::Locator::Stub> stub = server_->NewStub();
  const std::vector<LocateResult> located =
      LocateInBatches(*stub, centres, 8192);
  ASSERT_EQ(located.size(), centres.size());
  const std::string path =
      "/v1/datasets/terrain/hillshade/" + std::to_string(tile.z) + "/" +
      std::to_string(tile.x) + "/" + std::to_string(tile.y) + ".png";
  HillshadeOptions light;
  light.azimuth = 90;
  light.altitude = 20;
  light.z_factor = 4;
  HttpReply reply;
  ASSERT_TRUE(
      HttpGet(port(), path + "?azimuth=90&altitude=20&z_factor=4", &reply)
          .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  EXPECT_EQ(reply.headers.at("content-type"), "image/png");
  EXPECT_THAT(reply.headers.at("etag"), HasSubstr("-1-hillshade-90-20-4-1\""));
  RgbaImage image;
  ASSERT_TRUE(DecodeRgbaPng(reply.body, &image).ok());
  ASSERT_EQ(image.width, 256u);
  const std::vector<gis::testing::PointZ> hill =
      gis::testing::UtmHill(kHillSide);
  size_t faces = 0, shaded = 0;
  for (size_t i = 0; i < centres.size(); ++i) {
    const LocateResult& r = located[i];
    ASSERT_EQ(image.Alpha(i), r.has_value ? 255 : 0)
        << "pixel " << i % 256 << "," << i / 256;
    if (!r.has_value || r.type != LocationType::kFace) continue;
    ++faces;
    // The hill's facets are ~400 m across and the pixels ~25 m, so the
    // renderer's approximate centre is on the same facet but for a few
    // pixels next to edges. A batch answers corners by id: the hill's
    // point indices.
    std::array<Point2, 3> corners;
    std::array<double, 3> heights;
    for (int k = 0; k < 3; ++k) {
      const gis::testing::PointZ& p = hill.at(r.vertex_ids[k]);
      corners[k] = Point2{p.x, p.y};
      heights[k] = p.z;
    }
    const FacetGradient g = PlaneGradient(corners, heights);
    shaded += std::abs(int{image.Rgb(i)[0]} - int{Shade(g, light)}) <= 1;
  }
  EXPECT_GT(faces, 1000u);
  EXPECT_GT(shaded, faces * 99 / 100);

  HttpReply default_light;
  ASSERT_TRUE(HttpGet(port(), path, &default_light).ok());
  ASSERT_EQ(default_light.status, 200u);
  EXPECT_NE(default_light.headers.at("etag"), reply.headers.at("etag"));
  EXPECT_FALSE(default_light.body == reply.body) << "the light did not move";
  HttpReply again;
  ASSERT_TRUE(SendHttp(port(), "GET", path, &again, {},
                       {{"If-None-Match", default_light.headers.at("etag")}})
                  .ok());
  EXPECT_EQ(again.status, 304u);
}

TEST_F(TilesE2eTest, ETagsAnswer304UntilTheEncodingChanges) {
  const std::string path = TilePath(CornerTile());
  HttpReply first;
  ASSERT_TRUE(HttpGet(port(), path, &first).ok());
  ASSERT_EQ(first.status, 200u) << first.body;
  const std::string etag = first.headers.at("etag");
  EXPECT_THAT(etag, HasSubstr("-1-terrarium\""));
  EXPECT_EQ(first.headers.at("cache-control"), "public, max-age=60");

  for (const std::string& match :
       {etag, "W/" + etag, "\"other\", " + etag, std::string("*")}) {
    HttpReply again;
    ASSERT_TRUE(
        SendHttp(port(), "GET", path, &again, {}, {{"If-None-Match", match}})
            .ok());
    EXPECT_EQ(again.status, 304u) << match;
    EXPECT_TRUE(again.body.empty()) << again.body.size() << " bytes " << match;
    EXPECT_EQ(again.headers["etag"], etag) << match;
  }
  HttpReply stale;
  ASSERT_TRUE(SendHttp(port(), "GET", path, &stale, {},
                       {{"If-None-Match", "\"0-1-terrarium\""}})
                  .ok());
  EXPECT_EQ(stale.status, 200u);
  EXPECT_TRUE(stale.body == first.body) << "another tile";

  HttpReply mapbox;
  ASSERT_TRUE(SendHttp(port(), "GET", TilePath(CornerTile(), "mapbox"), &mapbox,
                       {}, {{"If-None-Match", etag}})
                  .ok());
  EXPECT_EQ(mapbox.status, 200u);
  EXPECT_NE(mapbox.headers.at("etag"), etag);
}

TEST_F(TilesE2eTest, TileJsonPointsAtTheTiles) {
  const JsonValue json =
      GetJson(port(), "/v1/datasets/terrain/tiles.json?encoding=mapbox");
  ASSERT_TRUE(std::holds_alternative<JsonObject>(json.value));
  EXPECT_EQ(json["tilejson"].string(), "3.0.0");
  EXPECT_EQ(json["encoding"].string(), "mapbox");
  EXPECT_EQ(json["scheme"].string(), "xyz");
  EXPECT_EQ(json["tileSize"].number(), 256);
  ASSERT_EQ(json["tiles"].array().size(), 1u);
  EXPECT_EQ(json["tiles"].array()[0].string(),
            "http://127.0.0.1/v1/datasets/terrain/tiles/{z}/{x}/{y}.png"
            "?encoding=mapbox");
  // The hill is centred at 15°E 49.6525°N and ~12 km wide.
  const JsonArray& bounds = json["bounds"].array();
  ASSERT_EQ(bounds.size(), 4u);
  EXPECT_LT(bounds[0].number(), 15);
  EXPECT_GT(bounds[2].number(), 15);
  EXPECT_LT(bounds[1].number(), 49.6525);
  EXPECT_GT(bounds[3].number(), 49.6525);
  const JsonArray& center = json["center"].array();
  ASSERT_EQ(center.size(), 3u);
  EXPECT_NEAR(center[0].number(), 15, 0.01);
  EXPECT_NEAR(center[1].number(), 49.6525, 0.01);
  // The hill's 11.6 km are ~17.9 km of Mercator there, and its 400 m
  // spacing ~620 m: pixels of at most that are zoom 9's (306 m; zoom 8's
  // are 611 m), and one tile spans the hill from zoom 11 down, so minzoom
  // is held to maxzoom.
  EXPECT_EQ(json["maxzoom"].number(), 9);
  EXPECT_EQ(json["minzoom"].number(), 9);
  EXPECT_EQ(center[2].number(), 9);
}

TEST_F(TilesE2eTest, RefusalsArePreciseAndTheServerKeepsServing) {
  struct Row {
    std::string method, target;
    unsigned http;
    Code code;
    std::string message;
  };
  const std::vector<Row> rows = {
      {"GET", "/v1/datasets/terrain/tiles/25/0/0.png", 400,
       Code::INVALID_ARGUMENT, "tile zoom '25' is not a whole number in 0..24"},
      {"GET", "/v1/datasets/terrain/tiles/3/8/0.png", 400,
       Code::INVALID_ARGUMENT, "tile x at zoom 3 '8' is not a whole number"},
      {"GET", "/v1/datasets/terrain/tiles/3/0/-1.png", 400,
       Code::INVALID_ARGUMENT, "tile y at zoom 3 '-1'"},
      {"GET",
       "/v1/datasets/terrain/tiles/1/" + std::string(5000, '9') + "/0.png", 400,
       Code::INVALID_ARGUMENT, "tile x at zoom 1"},
      {"GET", "/v1/datasets/terrain/tiles/0/0/0.png?encoding=rgb", 400,
       Code::INVALID_ARGUMENT, "unknown encoding 'rgb'"},
      {"GET", "/v1/datasets/terrain/hillshade/0/0/0.png?azimuth=400", 400,
       Code::INVALID_ARGUMENT, "azimuth '400' must be a number from 0 to 360"},
      {"GET", "/v1/datasets/terrain/hillshade/0/0/0.png?z_factor=nan", 400,
       Code::INVALID_ARGUMENT, "z_factor 'nan' must be a number above 0"},
      {"GET", "/v1/datasets/terrain/hillshade/30/0/0.png", 400,
       Code::INVALID_ARGUMENT, "tile zoom '30' is not a whole number"},
      {"GET", "/v1/datasets/terrain/hillshade/0/0.png", 404, Code::NOT_FOUND,
       "no API method"},
      {"GET", "/v1/datasets/plain/hillshade/0/0/0.png", 400,
       Code::FAILED_PRECONDITION, "dataset 'plain' has no CRS"},
      {"GET", "/v1/datasets/lava/tiles/0/0/0.png", 404, Code::NOT_FOUND,
       "unknown dataset 'lava'"},
      {"GET", "/v1/datasets/plain/tiles/0/0/0.png", 400,
       Code::FAILED_PRECONDITION, "dataset 'plain' has no CRS"},
      {"GET", "/v1/datasets/plain/tiles.json", 400, Code::FAILED_PRECONDITION,
       "dataset 'plain' has no CRS"},
      {"GET", "/v1/datasets/terrain/tiles/0/0.png", 404, Code::NOT_FOUND,
       "no API method"},
      {"GET", "/v1/datasets/terrain/tiles/0/0/0/0.png", 404, Code::NOT_FOUND,
       "no API method"},
      {"GET", "/v1/datasets/terrain/tiles/0/0/0.jpg", 404, Code::NOT_FOUND,
       "no API method"},
      {"GET", "/v1/datasets/terrain/elsewhere", 404, Code::NOT_FOUND,
       "no API method"},
      {"POST", "/v1/datasets/terrain/tiles/0/0/0.png", 405, Code::UNIMPLEMENTED,
       "'POST' is not allowed"},
      {"DELETE", "/v1/datasets/terrain/tiles.json", 405, Code::UNIMPLEMENTED,
       "'DELETE' is not allowed"},
  };
  for (const Row& row : rows) {
    HttpReply reply;
    ASSERT_TRUE(SendHttp(port(), row.method, row.target, &reply, "{}",
                         {{"Content-Type", "application/json"}})
                    .ok())
        << row.target;
    SCOPED_TRACE(row.method + " " + row.target.substr(0, 80));
    ExpectError(reply, row.http, row.code, row.message);
    if (row.http == 405) {
      EXPECT_EQ(reply.headers["allow"], "GET");
    }
  }
  HttpReply world;
  ASSERT_TRUE(HttpGet(port(), TilePath({0, 0, 0}), &world).ok());
  EXPECT_EQ(world.status, 200u) << world.body;
}

TEST(TilesTokenE2eTest, ATileWantsTheDataTokenAndIsPrivate) {
  ScratchDir dir;
  const std::string gpkg = gis::testing::UtmHillGeoPackage(5, dir.path());
  const std::string token_file = dir.path() + "/data.token";
  const std::string token = "tiles-data-token-0123456789abcdef";
  std::ofstream(token_file) << token << "\n";
  std::unique_ptr<LocatordWithHttp> server;
  const Status started = LocatordWithHttp::Start(
      "terrain=" + gpkg, {"--token-file", token_file}, &server, token);
  ASSERT_TRUE(started.ok()) << started.ToString();
  const std::string path = "/v1/datasets/terrain/tiles/0/0/0.png";
  HttpReply refused;
  ASSERT_TRUE(HttpGet(server->http_port(), path, &refused).ok());
  ExpectError(refused, 401, Code::UNAUTHENTICATED, "");
  HttpReply tile;
  ASSERT_TRUE(SendHttp(server->http_port(), "GET", path, &tile, {},
                       {{"Authorization", "Bearer " + token}})
                  .ok());
  EXPECT_EQ(tile.status, 200u) << tile.body;
  EXPECT_EQ(tile.headers["cache-control"], "private, max-age=60");
}

}  // namespace
}  // namespace locator::test
