// Quantized-mesh tiles of a TIN in UTM zone 33N (EPSG:32633), rendered over
// four levels where the data is and decoded by an independent decoder
// (@here/quantized-mesh-decoder under node, node_decoder.h):
//  (a) every decoded vertex lies on the TIN: its height is the engine's
//      Locate at its longitude and latitude, transformed to the dataset's
//      CRS by the test's own PROJ transformer, within the height quantum
//      and the facet's slope times the position quantum; and at every
//      vertex of the TIN inside a tile, the tile's surface is within the
//      level's geometric error of the TIN (what layer.json promises);
//  (b) neighbouring tiles list the same vertices on their shared side:
//      the same position along it and the same height within the two
//      tiles' quanta;
//  (c) the header's bounding sphere holds every decoded vertex, in ECEF
//      computed here from the WGS84 definition.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/tiles/quantized_mesh/geographic_tile.h"
#include "server/tiles/quantized_mesh/quantized_mesh_tile.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/tiles/quantized_mesh/node_decoder.h"

namespace locator {
namespace {

using test::DecodedTile;
using test::ScratchDir;

// The data: a 3 km square of the zone, near 15°E 49.6°N.
constexpr char kUtm33[] = "EPSG:32633";
constexpr double kWest = 500000, kSouth = 5500000, kSide = 3000;
constexpr double kMetresPerDegree = 111320;

double Height(const Point2& p) {
  return 400 +
         120 * std::sin((p.x - kWest) / 700) * std::cos((p.y - kSouth) / 500) +
         0.01 * (p.y - kSouth);
}

// The slope (|gradient|) of the facet `r` found: the plane through its
// corners at their Heights.
double Slope(const LocateResult& r) {
  const std::array<Point2, 3>& v = r.vertices;
  const double h0 = Height(v[0]), h1 = Height(v[1]), h2 = Height(v[2]);
  const double ax = v[1].x - v[0].x, ay = v[1].y - v[0].y;
  const double bx = v[2].x - v[0].x, by = v[2].y - v[0].y;
  const double det = ax * by - ay * bx;
  const double gx = ((h1 - h0) * by - (h2 - h0) * ay) / det;
  const double gy = ((h2 - h0) * ax - (h1 - h0) * bx) / det;
  return std::hypot(gx, gy);
}

std::array<double, 3> Ecef(double lon, double lat, double h) {
  const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
  const double phi = lat * M_PI / 180, lambda = lon * M_PI / 180;
  const double n = a / std::sqrt(1 - e2 * std::sin(phi) * std::sin(phi));
  return {(n + h) * std::cos(phi) * std::cos(lambda),
          (n + h) * std::cos(phi) * std::sin(lambda),
          (n * (1 - e2) + h) * std::sin(phi)};
}

class QuantizedMeshDecoderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dataset_ = GenerateUniform(20000, 17);
    for (Point2& p : dataset_.points) {
      p = Point2{kWest + p.x * kSide, kSouth + p.y * kSide};
      dataset_.values.push_back(Height(p));
    }
    dataset_.crs = kUtm33;
    Dataset copy = dataset_;
    StatusOr<std::unique_ptr<Engine>> built =
        Engine::Create(std::move(copy), EngineOptions());
    ASSERT_TRUE(built.ok()) << built.status().ToString();
    engine_ = *std::move(built);
    StatusOr<std::unique_ptr<gis::CrsTransformer>> to_utm =
        gis::CrsTransformer::Create("EPSG:4326", kUtm33);
    ASSERT_TRUE(to_utm.ok()) << to_utm.status().ToString();
    to_utm_ = *std::move(to_utm);
  }

  Dataset dataset_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<gis::CrsTransformer> to_utm_;
};

TEST_F(QuantizedMeshDecoderTest, TilesLieOnTheTinStitchAndFitTheirSpheres) {
  // The data's corners in degrees, for the tiles that meet it.
  std::vector<Point2> corners = {{kWest, kSouth},
                                 {kWest + kSide, kSouth},
                                 {kWest, kSouth + kSide},
                                 {kWest + kSide, kSouth + kSide}};
  ASSERT_TRUE(to_utm_->ToRequest(corners).ok());
  BoundingBox data;
  for (const Point2& p : corners) data.Extend(p);
  std::vector<Point2> tin_lon_lat = dataset_.points;
  ASSERT_TRUE(to_utm_->ToRequest(tin_lon_lat).ok());

  ScratchDir dir;
  std::vector<GeographicTile> tiles;
  std::vector<std::string> files;
  for (uint32_t z : {10u, 12u, 14u, 15u}) {
    const double side = std::ldexp(180.0, -static_cast<int>(z));
    for (uint32_t x = (data.min_x + 180) / side; x <= (data.max_x + 180) / side;
         ++x) {
      for (uint32_t y = (data.min_y + 90) / side; y <= (data.max_y + 90) / side;
           ++y) {
        const GeographicTile tile{z, x, y};
        StatusOr<std::string> bytes =
            RenderQuantizedMesh(*engine_, "utm", tile);
        ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
        files.push_back(dir.path() + "/" + std::to_string(z) + "_" +
                        std::to_string(x) + "_" + std::to_string(y) +
                        ".terrain");
        std::ofstream(files.back(), std::ios::binary) << *bytes;
        tiles.push_back(tile);
      }
    }
  }
  std::vector<DecodedTile> decoded;
  const Status read = test::DecodeWithNode(files, &decoded);
  ASSERT_TRUE(read.ok()) << read.ToString();

  std::map<std::array<uint32_t, 3>, size_t> index_of;
  size_t vertices = 0, tin_vertices_checked = 0, off_hull = 0;
  for (size_t k = 0; k < tiles.size(); ++k) {
    const GeographicTile& tile = tiles[k];
    const DecodedTile& t = decoded[k];
    index_of[{tile.z, tile.x, tile.y}] = k;
    const BoundingBox box = tile.Box();
    const double quantum = (t.max_height - t.min_height) / 32767;
    // How far rounding to u and v moves a vertex on the ground: half a
    // step both ways, a degree of longitude no longer than one of
    // latitude.
    const double position_quantum =
        std::sqrt(2.0) * box.height() / 32767 / 2 * kMetresPerDegree;
    const double error = GeometricError(tile.z);
    std::vector<Point2> lon_lat(t.vertices.size());
    for (size_t i = 0; i < t.vertices.size(); ++i) {
      lon_lat[i] = {box.min_x + t.vertices[i][0] * box.width() / 32767,
                    box.min_y + t.vertices[i][1] * box.height() / 32767};
    }

    // (a) Each vertex on the TIN, within the height quantum and the
    // slope (the steepest facet at the vertex or a corner of its
    // quantization cell, where the vertex was before rounding) times the
    // position quantum.
    std::vector<Point2> utm = lon_lat;
    ASSERT_TRUE(to_utm_->ToDataset(utm).ok());
    const double half_step = box.width() / 32767 / 2;
    for (size_t i = 0; i < utm.size(); ++i) {
      std::vector<Point2> cell;
      for (double dx : {-half_step, half_step}) {
        for (double dy : {-half_step, half_step}) {
          cell.push_back({lon_lat[i].x + dx, lon_lat[i].y + dy});
        }
      }
      ASSERT_TRUE(to_utm_->ToDataset(cell).ok());
      cell.push_back(utm[i]);
      double slope = 0;
      // A vertex on the hull may be quantized to just outside it: then the
      // nearest corner of its cell inside stands for where it was.
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point2& p : cell) {
        LocateResult c;
        ASSERT_TRUE(engine_->Locate(p, &c).ok());
        if (c.triangle_id >= 0) slope = std::max(slope, Slope(c));
        if (c.has_value) {
          nearest = std::min(nearest, std::abs(t.Height(i) - c.value));
        }
      }
      LocateResult r;
      ASSERT_TRUE(engine_->Locate(utm[i], &r).ok());
      if (!r.has_value) {
        ++off_hull;
        EXPECT_EQ(r.type, LocationType::kOutsideConvexHull);
        EXPECT_LE(nearest, quantum / 2 + 2 * slope * position_quantum + 1e-6)
            << "tile " << tile.z << "/" << tile.x << "/" << tile.y << " vertex "
            << i;
        continue;
      }
      EXPECT_LE(std::abs(t.Height(i) - r.value),
                quantum / 2 + slope * position_quantum + 1e-6)
          << "tile " << tile.z << "/" << tile.x << "/" << tile.y << " vertex "
          << i << " at " << lon_lat[i].x << ", " << lon_lat[i].y;
    }
    vertices += utm.size();
    // The steepest facet of the tile's vertices, for the TIN's vertices
    // between them.
    double slope_bound = 0;
    for (const Point2& p : utm) {
      LocateResult c;
      ASSERT_TRUE(engine_->Locate(p, &c).ok());
      if (c.triangle_id >= 0) slope_bound = std::max(slope_bound, Slope(c));
    }
    // ... and the TIN's vertices within the level's geometric error of the
    // tile's surface.
    for (size_t p = 0; p < tin_lon_lat.size(); ++p) {
      const Point2& q = tin_lon_lat[p];
      if (!box.Contains(q)) continue;
      for (const auto& tri : t.triangles) {
        const Point2 &a = lon_lat[tri[0]], &b = lon_lat[tri[1]],
                     &c = lon_lat[tri[2]];
        const double det =
            (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const double s =
            ((q.x - a.x) * (c.y - a.y) - (c.x - a.x) * (q.y - a.y)) / det;
        const double u =
            ((b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y)) / det;
        if (!(s >= 0 && u >= 0 && s + u <= 1)) continue;
        const double h = t.Height(tri[0]) +
                         s * (t.Height(tri[1]) - t.Height(tri[0])) +
                         u * (t.Height(tri[2]) - t.Height(tri[0]));
        EXPECT_LE(std::abs(h - dataset_.values[p]),
                  error + quantum + slope_bound * position_quantum + 1e-3)
            << "tile " << tile.z << "/" << tile.x << "/" << tile.y
            << ", TIN vertex " << p;
        ++tin_vertices_checked;
        break;
      }
    }

    // (c) The sphere holds every vertex.
    for (size_t i = 0; i < t.vertices.size(); ++i) {
      const std::array<double, 3> e =
          Ecef(lon_lat[i].x, lon_lat[i].y, t.Height(i));
      const double d =
          std::hypot(e[0] - t.sphere_centre[0], e[1] - t.sphere_centre[1],
                     e[2] - t.sphere_centre[2]);
      EXPECT_LE(d, t.sphere_radius * (1 + 1e-9) + 1e-3)
          << "tile " << tile.z << "/" << tile.x << "/" << tile.y;
    }
  }
  // Most TIN vertices lie in some tile's triangle at each of four levels
  // (those on the hull may round just outside).
  EXPECT_GT(tin_vertices_checked, 4 * dataset_.points.size() * 9 / 10);
  EXPECT_GT(vertices, 1000u);
  EXPECT_LT(off_hull, vertices / 4);

  // (b) Shared sides: east of each tile against west of the next, north
  // against south.
  size_t shared = 0;
  for (size_t k = 0; k < tiles.size(); ++k) {
    const GeographicTile& tile = tiles[k];
    for (const auto& [dx, dy, mine, theirs, along] :
         {std::tuple{1, 0, 2, 0, 1}, std::tuple{0, 1, 3, 1, 0}}) {
      const auto other = index_of.find({tile.z, tile.x + dx, tile.y + dy});
      if (other == index_of.end()) continue;
      const DecodedTile& a = decoded[k];
      const DecodedTile& b = decoded[other->second];
      const std::vector<uint32_t>& ea = a.edges[mine];
      const std::vector<uint32_t>& eb = b.edges[theirs];
      ASSERT_EQ(ea.size(), eb.size())
          << "tile " << tile.z << "/" << tile.x << "/" << tile.y
          << (dx ? " east" : " north");
      const double quanta = (a.max_height - a.min_height) / 32767 / 2 +
                            (b.max_height - b.min_height) / 32767 / 2;
      for (size_t i = 0; i < ea.size(); ++i) {
        EXPECT_EQ(a.vertices[ea[i]][along], b.vertices[eb[i]][along]);
        EXPECT_EQ(a.vertices[ea[i]][1 - along], dx ? 32767u : 32767u)
            << "not on the side";
        EXPECT_EQ(b.vertices[eb[i]][1 - along], 0u) << "not on the side";
        EXPECT_LE(std::abs(a.Height(ea[i]) - b.Height(eb[i])), quanta + 1e-6);
        ++shared;
      }
    }
  }
  EXPECT_GT(shared, 50u);
}

TEST_F(QuantizedMeshDecoderTest, CoarseTilesHaveFewerVerticesThanTheTin) {
  // Level 12's error (18.8 m) lets the simplification drop most of the
  // 20000 vertices; level 17's (0.59 m) keeps more per area.
  std::vector<Point2> centre = {{kWest + kSide / 2, kSouth + kSide / 2}};
  ASSERT_TRUE(to_utm_->ToRequest(centre).ok());
  const double side = std::ldexp(180.0, -12);
  const GeographicTile tile{12,
                            static_cast<uint32_t>((centre[0].x + 180) / side),
                            static_cast<uint32_t>((centre[0].y + 90) / side)};
  ScratchDir dir;
  StatusOr<std::string> bytes = RenderQuantizedMesh(*engine_, "utm", tile);
  ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
  const std::string file = dir.path() + "/tile.terrain";
  std::ofstream(file, std::ios::binary) << *bytes;
  std::vector<DecodedTile> decoded;
  const Status read = test::DecodeWithNode({file}, &decoded);
  ASSERT_TRUE(read.ok()) << read.ToString();
  EXPECT_GT(decoded[0].vertices.size(), 20u);
  EXPECT_LT(decoded[0].vertices.size(), 2000u);
}

}  // namespace
}  // namespace locator
