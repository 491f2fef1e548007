// SimplifyClippedMesh on clipped pieces of a smooth TIN: every vertex of
// the piece is within the tolerance of the simplified surface, the
// footprint keeps its area, the mesh gets smaller as the tolerance grows,
// and two boxes that share a side keep the same vertices on it.

#include "server/core/patch/simplify_clipped_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "tests/server/tiles/quantized_mesh/mesh_area.h"

namespace locator {
namespace {

// The height of `m`'s surface at q, if a triangle holds it.
std::optional<double> SurfaceAt(const ClippedMesh& m, const Point2& q) {
  for (const auto& t : m.triangles) {
    const Point2 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double s =
        ((q.x - a.x) * (c.y - a.y) - (c.x - a.x) * (q.y - a.y)) / det;
    const double u =
        ((b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y)) / det;
    constexpr double kSlack = 1e-12;
    if (s < -kSlack || u < -kSlack || s + u > 1 + kSlack) continue;
    const double h0 = m.heights[t[0]];
    return h0 + s * (m.heights[t[1]] - h0) + u * (m.heights[t[2]] - h0);
  }
  return std::nullopt;
}

// A smooth hill sampled at 5000 uniform points of the unit square, with a
// hole cut by nothing: its hull is the footprint.
std::unique_ptr<Engine> Hill() {
  Dataset d = GenerateUniform(5000, 11);
  for (const Point2& p : d.points) {
    d.values.push_back(100 * std::sin(3 * p.x) * std::cos(4 * p.y));
  }
  StatusOr<std::unique_ptr<Engine>> built =
      Engine::Create(std::move(d), EngineOptions());
  EXPECT_TRUE(built.ok()) << built.status().ToString();
  return built.ok() ? *std::move(built) : nullptr;
}

ClippedMesh Piece(const Engine& engine, const BoundingBox& box) {
  MeshPatch patch;
  EXPECT_TRUE(engine.MeshInBox(box, 1 << 20, &patch).ok());
  return ClipMeshToBox(patch, box);
}

TEST(SimplifyClippedMeshTest, EveryVertexIsWithinTheTolerance) {
  const std::unique_ptr<Engine> engine = Hill();
  ASSERT_NE(engine, nullptr);
  // Half of the square: its west, south and north sides cross the hull.
  const ClippedMesh piece = Piece(*engine, {0, 0, 0.5, 1});
  size_t previous = piece.size() + 1;
  for (double tolerance : {0.01, 0.5, 2.0, 10.0}) {
    const ClippedMesh simple = SimplifyClippedMesh(piece, tolerance, 1);
    EXPECT_LT(simple.size(), previous) << tolerance;
    previous = simple.size();
    EXPECT_NEAR(Area(simple), Area(piece), 1e-12);
    for (size_t v = 0; v < piece.size(); ++v) {
      const std::optional<double> h = SurfaceAt(simple, piece.points[v]);
      ASSERT_TRUE(h.has_value()) << "vertex " << v << " is outside";
      EXPECT_LE(std::abs(*h - piece.heights[v]), tolerance + 1e-9)
          << "vertex " << v << ", tolerance " << tolerance;
    }
  }
  // A coarse tolerance leaves a small fraction.
  EXPECT_LT(previous, piece.size() / 10);
}

TEST(SimplifyClippedMeshTest, BoxesSharingASideKeepTheSameVerticesOnIt) {
  const std::unique_ptr<Engine> engine = Hill();
  ASSERT_NE(engine, nullptr);
  const ClippedMesh west =
      SimplifyClippedMesh(Piece(*engine, {0, 0, 0.5, 1}), 2.0, 1);
  const ClippedMesh east =
      SimplifyClippedMesh(Piece(*engine, {0.5, 0, 1, 1}), 2.0, 0.5);
  const auto on_side = [](const ClippedMesh& m, BoxSide s) {
    std::vector<std::tuple<double, double, double>> out;
    for (size_t v = 0; v < m.size(); ++v) {
      if (m.sides[v] & s) {
        out.emplace_back(m.points[v].x, m.points[v].y, m.heights[v]);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto shared = on_side(west, kEastSide);
  EXPECT_EQ(shared, on_side(east, kWestSide));
  EXPECT_GE(shared.size(), 2u);
  // Fewer than the unsimplified side holds.
  EXPECT_LT(shared.size(),
            on_side(Piece(*engine, {0, 0, 0.5, 1}), kEastSide).size());
}

TEST(SimplifyClippedMeshTest, CrossingBoundariesLeaveTheMeshAsItCame) {
  // Two triangles that overlap: no planar mesh, which CGAL refuses to
  // constrain; the mesh comes back whole rather than crash or guess.
  ClippedMesh m;
  m.points = {{0, 0}, {2, 0}, {0, 2}, {1, 1.5}, {-1, 0.5}, {1, -1}};
  m.heights = {0, 1, 2, 3, 4, 5};
  m.sides.assign(6, 0);
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  const ClippedMesh simple = SimplifyClippedMesh(m, 100, 1);
  EXPECT_EQ(simple.triangles, m.triangles);
  EXPECT_EQ(simple.size(), m.size());
}

TEST(SimplifyClippedMeshTest, EmptyMeshStaysEmpty) {
  EXPECT_EQ(SimplifyClippedMesh(ClippedMesh(), 1, 1).size(), 0u);
}

}  // namespace
}  // namespace locator
