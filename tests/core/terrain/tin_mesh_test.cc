// TinMesh: insertion keeps a valid, constrained Delaunay triangulation
// (checked after every insertion), inside triangles, on edges, on
// constrained and boundary edges.

#include "server/core/terrain/tin_mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "server/core/cgal/orientation.h"
#include "server/core/geometry/circle.h"

namespace locator {
namespace {

// Checks the invariants of tin_mesh.h and that every unconstrained edge is
// locally Delaunay.
void ExpectValid(const TinMesh& mesh) {
  for (uint32_t t = 0; t < mesh.num_triangles(); ++t) {
    const Point2& a = mesh.point(mesh.Corner(t, 0));
    const Point2& b = mesh.point(mesh.Corner(t, 1));
    const Point2& c = mesh.point(mesh.Corner(t, 2));
    ASSERT_EQ(Orientation(a, b, c), Side::kLeft) << "triangle " << t;
    for (int i = 0; i < 3; ++i) {
      const uint32_t h = 3 * t + i;
      const uint32_t g = mesh.Twin(h);
      if (g == TinMesh::kNoTwin) {
        ASSERT_TRUE(mesh.IsConstrained(h));
        continue;
      }
      ASSERT_EQ(mesh.Twin(g), h);
      ASSERT_EQ(mesh.Origin(g), mesh.Origin(TinMesh::Next(h)));
      ASSERT_EQ(mesh.Origin(h), mesh.Origin(TinMesh::Next(g)));
      ASSERT_EQ(mesh.IsConstrained(g), mesh.IsConstrained(h));
      if (mesh.IsConstrained(h)) continue;
      const Point2& opposite = mesh.point(mesh.Origin(TinMesh::Prev(g)));
      const Point2& p = mesh.point(mesh.Origin(h));
      const Point2& q = mesh.point(mesh.Origin(TinMesh::Next(h)));
      const Point2& r = mesh.point(mesh.Origin(TinMesh::Prev(h)));
      ASSERT_FALSE(InsideCircumcircle(p, q, r, opposite))
          << "edge " << h << " is not locally Delaunay";
    }
  }
}

// The triangle holding p (closed), by brute force.
uint32_t Locate(const TinMesh& mesh, const Point2& p) {
  for (uint32_t t = 0; t < mesh.num_triangles(); ++t) {
    bool inside = true;
    for (int i = 0; i < 3; ++i) {
      inside &= Orientation(mesh.point(mesh.Corner(t, i)),
                            mesh.point(mesh.Corner(t, (i + 1) % 3)),
                            p) != Side::kRight;
    }
    if (inside) return t;
  }
  return TinMesh::kNone;
}

// The square [0, 64]^2 in two triangles, its diagonal constrained.
TinMesh Square(TinMesh::Coordinates coordinates) {
  TinMesh mesh(coordinates);
  const uint32_t a = mesh.AddVertex({0, 0}), b = mesh.AddVertex({64, 0});
  const uint32_t c = mesh.AddVertex({64, 64}), d = mesh.AddVertex({0, 64});
  const uint32_t lower = mesh.AddTriangle(a, b, c);  // diagonal: c -> a
  const uint32_t upper = mesh.AddTriangle(a, c, d);  // diagonal: a -> c
  mesh.Link(3 * lower + 2, 3 * upper);
  mesh.Constrain(3 * lower + 2);
  return mesh;
}

// Both kinds of predicates: CGAL's on any doubles, the integer ones on
// grid coordinates.
class TinMeshTest : public ::testing::TestWithParam<TinMesh::Coordinates> {};

TEST_P(TinMeshTest, InsertionsKeepAConstrainedDelaunayMesh) {
  TinMesh mesh = Square(GetParam());
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coordinate(0, 64);
  std::set<std::pair<int, int>> used = {{0, 0}, {64, 0}, {64, 64}, {0, 64}};
  for (int k = 0; k < 400; ++k) {
    // Integer points: many fall on edges, the diagonal and the boundary.
    Point2 p;
    if (k % 5 == 0) {
      const int s = coordinate(rng);
      p = k % 10 == 0 ? Point2{double(s), double(s)} : Point2{double(s), 0};
    } else {
      p = {double(coordinate(rng)), double(coordinate(rng))};
    }
    if (!used.insert({int(p.x), int(p.y)}).second) continue;
    const uint32_t t = Locate(mesh, p);
    ASSERT_NE(t, TinMesh::kNone);
    const size_t before = mesh.num_triangles();
    ASSERT_TRUE(mesh.Insert(mesh.AddVertex(p), t));
    ASSERT_NO_FATAL_FAILURE(ExpectValid(mesh));
    ASSERT_GE(mesh.touched().size(), mesh.num_triangles() - before + 1);
  }
  // Euler: 2V - 2 - (hull vertices) triangles; the hull is the square's
  // border with the points inserted on it.
  uint32_t hull_vertices = 0;
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    const Point2& p = mesh.point(v);
    hull_vertices += p.x == 0 || p.y == 0 || p.x == 64 || p.y == 64;
  }
  EXPECT_EQ(mesh.num_triangles(), 2 * mesh.num_vertices() - 2 - hull_vertices);
  // The diagonal is still covered by constrained edges: its length is the
  // sum of theirs.
  double diagonal = 0;
  for (uint32_t h = 0; h < 3 * mesh.num_triangles(); ++h) {
    const Point2& p = mesh.point(mesh.Origin(h));
    const Point2& q = mesh.point(mesh.Origin(TinMesh::Next(h)));
    if (mesh.Twin(h) != TinMesh::kNoTwin && mesh.IsConstrained(h) &&
        p.x < q.x) {
      EXPECT_EQ(p.x, p.y);
      EXPECT_EQ(q.x, q.y);
      diagonal += q.x - p.x;
    }
  }
  EXPECT_EQ(diagonal, 64);
}

TEST_P(TinMeshTest, RefusesPointsOutsideTheTriangleOrAtACorner) {
  TinMesh mesh = Square(GetParam());
  EXPECT_FALSE(mesh.Insert(mesh.AddVertex({10, 50}), 0));  // in the other
  EXPECT_FALSE(mesh.Insert(mesh.AddVertex({64, 0}), 0));   // a corner
  ExpectValid(mesh);
  EXPECT_EQ(mesh.num_triangles(), 2u);
}

INSTANTIATE_TEST_SUITE_P(
    BothPredicates, TinMeshTest,
    ::testing::Values(TinMesh::Coordinates::kAnyDouble,
                      TinMesh::Coordinates::kGridIntegers));

}  // namespace
}  // namespace locator
