// ClipMeshToBox and Engine::MeshInBox on a real TIN (2000 uniform points,
// random heights): cut into a 4 x 4 grid of boxes, the pieces cover exactly
// the TIN's area, every vertex's height is the engine's Locate value at its
// position, and boxes sharing a side list the same vertices on it, bit for
// bit.

#include "server/core/patch/clipped_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "tests/server/tiles/quantized_mesh/mesh_area.h"

namespace locator {
namespace {

std::unique_ptr<Engine> RandomTin() {
  Dataset d = GenerateUniform(2000, 3);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> height(-50, 50);
  for (size_t i = 0; i < d.points.size(); ++i)
    d.values.push_back(height(random));
  StatusOr<std::unique_ptr<Engine>> built =
      Engine::Create(std::move(d), EngineOptions());
  EXPECT_TRUE(built.ok()) << built.status().ToString();
  return built.ok() ? *std::move(built) : nullptr;
}

TEST(ClippedMeshTest, GridOfBoxesCoversTheTinAndSharesItsSides) {
  const std::unique_ptr<Engine> engine = RandomTin();
  ASSERT_NE(engine, nullptr);
  MeshPatch all;
  ASSERT_TRUE(engine->MeshInBox({-1, -1, 2, 2}, 1 << 20, &all).ok());
  ASSERT_EQ(all.size(), 2000u);
  ClippedMesh whole = ClipMeshToBox(all, {-1, -1, 2, 2});
  const double tin_area = Area(whole);
  EXPECT_GT(tin_area, 0.9);

  constexpr int kBoxes = 4;
  const double side = 0.25;
  double area = 0;
  size_t off_hull = 0;
  // (column, row) -> the box's mesh.
  std::map<std::pair<int, int>, ClippedMesh> pieces;
  for (int i = 0; i < kBoxes; ++i) {
    for (int j = 0; j < kBoxes; ++j) {
      const BoundingBox box{i * side, j * side, (i + 1) * side, (j + 1) * side};
      MeshPatch patch;
      ASSERT_TRUE(engine->MeshInBox(box, 1 << 20, &patch).ok());
      ClippedMesh piece = ClipMeshToBox(patch, box);
      for (const auto& t : piece.triangles) {
        EXPECT_GT(TwiceArea(piece, t), 0) << "not counter-clockwise";
      }
      area += Area(piece);
      for (size_t v = 0; v < piece.size(); ++v) {
        const Point2& p = piece.points[v];
        ASSERT_TRUE(box.Contains(p));
        EXPECT_EQ((piece.sides[v] & kWestSide) != 0, p.x == box.min_x);
        EXPECT_EQ((piece.sides[v] & kNorthSide) != 0, p.y == box.max_y);
        LocateResult r;
        ASSERT_TRUE(engine->Locate(p, &r).ok());
        if (!r.has_value) {
          // Where a hull edge crosses a side, the crossing may round to
          // just outside the hull.
          EXPECT_EQ(r.type, LocationType::kOutsideConvexHull);
          EXPECT_NE(piece.sides[v], 0);
          ++off_hull;
          continue;
        }
        EXPECT_NEAR(piece.heights[v], r.value, 1e-9) << p.x << ", " << p.y;
      }
      pieces[{i, j}] = std::move(piece);
    }
  }
  EXPECT_NEAR(area, tin_area, 1e-9);
  EXPECT_LE(off_hull, 12u);  // two per inner grid line

  // The vertices on a side, as (position, height), sorted along it.
  const auto on_side = [](const ClippedMesh& m, BoxSide s) {
    std::vector<std::tuple<double, double, double>> out;
    for (size_t v = 0; v < m.size(); ++v) {
      if (m.sides[v] & s)
        out.emplace_back(m.points[v].x, m.points[v].y, m.heights[v]);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  size_t shared = 0;
  for (int i = 0; i < kBoxes; ++i) {
    for (int j = 0; j < kBoxes; ++j) {
      if (i + 1 < kBoxes) {
        const auto a = on_side(pieces[{i, j}], kEastSide);
        EXPECT_EQ(a, on_side(pieces[{i + 1, j}], kWestSide)) << i << "," << j;
        shared += a.size();
      }
      if (j + 1 < kBoxes) {
        const auto a = on_side(pieces[{i, j}], kNorthSide);
        EXPECT_EQ(a, on_side(pieces[{i, j + 1}], kSouthSide)) << i << "," << j;
        shared += a.size();
      }
    }
  }
  EXPECT_GT(shared, 100u);
}

TEST(ClippedMeshTest, MeshInBoxRefusesMoreVerticesThanItsLimit) {
  const std::unique_ptr<Engine> engine = RandomTin();
  ASSERT_NE(engine, nullptr);
  MeshPatch patch;
  const Status status = engine->MeshInBox({0, 0, 1, 1}, 100, &patch);
  EXPECT_EQ(status.code(), Status::Code::kResourceExhausted);
  EXPECT_NE(status.message().find("more than 100 vertices"), std::string::npos);
  EXPECT_EQ(patch.size(), 0u);
  EXPECT_EQ(engine->MeshInBox({0, 0, NAN, 1}, 100, &patch).code(),
            Status::Code::kInvalidArgument);
  ASSERT_TRUE(engine->MeshInBox({5, 5, 6, 6}, 100, &patch).ok());
  EXPECT_EQ(patch.size(), 0u);
}

TEST(ClippedMeshTest, UnmappedAndClockwiseTrianglesAreHandled) {
  MeshPatch patch;
  patch.points = {{0, 0}, {0, 1}, {1, 0}, {NAN, 0}};  // clockwise 0 1 2
  patch.heights = {0, 1, 2, 3};
  patch.keys = {0, 1, 2, 3};
  patch.triangles = {{0, 1, 2}, {0, 2, 3}};
  const ClippedMesh m = ClipMeshToBox(patch, {0, 0, 1, 1});
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_NEAR(Area(m), 0.5, 1e-12);
}

TEST(ClippedMeshTest, AVertexOnASideLeavesAlongTheSideToACorner) {
  // Vertex 0 is on the west side; the triangle covers the south-west
  // corner, which the piece reaches along the west side from it.
  MeshPatch patch;
  patch.points = {{0, 0.5}, {-1, -1}, {1, -1}};
  for (const Point2& p : patch.points) patch.heights.push_back(p.x + 2 * p.y);
  patch.keys = {0, 1, 2};
  patch.triangles = {{0, 1, 2}};
  const BoundingBox box{0, 0, 1, 1};
  const ClippedMesh m = ClipMeshToBox(patch, box);
  EXPECT_NEAR(Area(m), 1.0 / 12, 1e-12);
  for (size_t v = 0; v < m.size(); ++v) {
    EXPECT_TRUE(box.Contains(m.points[v])) << m.points[v].x;
    EXPECT_NEAR(m.heights[v], m.points[v].x + 2 * m.points[v].y, 1e-12);
  }
}

}  // namespace
}  // namespace locator
