// RenderQuantizedMesh and LayerJson on datasets placed where tiles are
// hard: across the antimeridian (UTM zone 60), where PROJ puts a triangle's
// corners 360° apart, and far from every tile asked for.

#include "server/tiles/quantized_mesh/quantized_mesh_tile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include "locator/dataset_sources.h"
#include "locator/engine.h"

namespace locator {
namespace {

// The radius of the bounding sphere in a quantized-mesh header.
double SphereRadius(const std::string& tile) {
  double radius = 0;
  EXPECT_GE(tile.size(), 64u);
  std::memcpy(&radius, tile.data() + 56, sizeof radius);
  return radius;
}

// 2000 points 130 km across round 180°E 45°N, in UTM zone 60 (central
// meridian 177°E), with heights.
std::unique_ptr<Engine> AcrossTheAntimeridian() {
  Dataset d = GenerateUniform(2000, 9);
  for (Point2& p : d.points) {
    p = {650000 + 130000 * p.x, 4980000 + 40000 * p.y};
    d.values.push_back(100 + p.y / 1e4);
  }
  d.crs = "EPSG:32660";
  StatusOr<std::unique_ptr<Engine>> built =
      Engine::Create(std::move(d), EngineOptions());
  EXPECT_TRUE(built.ok()) << built.status().ToString();
  return built.ok() ? *std::move(built) : nullptr;
}

TEST(QuantizedMeshTileTest, TrianglesAcrossTheAntimeridianLeaveASeam) {
  const std::unique_ptr<Engine> engine = AcrossTheAntimeridian();
  ASSERT_NE(engine, nullptr);
  // Level 0's eastern tile holds the data up to 180°: its ~100 km, not
  // triangles spanning the 180° of longitude between. (West of 180° is
  // outside the area of use of zone 60, which PROJ does not map to; the
  // western tile holds at most the same seam.)
  for (uint32_t x : {0u, 1u}) {
    StatusOr<std::string> tile =
        RenderQuantizedMesh(*engine, "zone60", GeographicTile{0, x, 0});
    ASSERT_TRUE(tile.ok()) << tile.status().ToString();
    if (x == 1) EXPECT_GT(tile->size(), 200u) << "no data";
    EXPECT_LT(SphereRadius(*tile), 200e3) << "x " << x;
  }
}

TEST(QuantizedMeshTileTest, ATileFarFromTheDataHasNoVertices) {
  const std::unique_ptr<Engine> engine = AcrossTheAntimeridian();
  ASSERT_NE(engine, nullptr);
  StatusOr<std::string> tile =
      RenderQuantizedMesh(*engine, "zone60", GeographicTile{5, 10, 3});
  ASSERT_TRUE(tile.ok()) << tile.status().ToString();
  EXPECT_EQ(tile->size(), 88u + 4 + 4 + 4 * 4);
}

}  // namespace
}  // namespace locator
