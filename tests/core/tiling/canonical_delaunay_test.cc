// The canonical tie-break (server/core/tiling/canonical_delaunay.h): the
// predicate matches CGAL's perturbed one, and every build gives the one
// canonical triangulation of co-circular points, whatever the order.

#include "server/core/tiling/canonical_delaunay.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/orientation.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/tiling/mesh_vectors.h"
#include "server/core/tiling/tiled_build.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CoordinateTriangle = std::array<std::pair<double, double>, 3>;

// The triangles of `mesh` by their corners' coordinates (ids change with
// the input order; coordinates do not).
std::set<CoordinateTriangle> TrianglesByCoordinates(const ServingMesh& mesh) {
  std::set<CoordinateTriangle> triangles;
  for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
    CoordinateTriangle t;
    for (int i = 0; i < 3; ++i) {
      t[i] = {mesh.CornerPoint(f, i).x, mesh.CornerPoint(f, i).y};
    }
    std::sort(t.begin(), t.end());
    triangles.insert(t);
  }
  return triangles;
}

// CGAL's own perturbed predicate, as its insertion uses it.
bool CgalInside(const Point2& a, const Point2& b, const Point2& c,
                const Point2& d) {
  static const CGAL::Delaunay_triangulation_2<Kernel> dt;
  const auto p = [](const Point2& q) { return Kernel::Point_2(q.x, q.y); };
  return dt.side_of_oriented_circle(p(a), p(b), p(c), p(d), true) ==
         CGAL::ON_POSITIVE_SIDE;
}

TEST(CanonicalDelaunayTest, PredicateMatchesCgalsPerturbedOne) {
  const Dataset circle = test::CocircularDataset();
  const std::vector<Point2> ring(circle.points.begin(),
                                 circle.points.begin() + 180);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<size_t> pick(0, ring.size() - 1);
  size_t cocircular = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<Point2, 4> q;
    if (trial % 4 == 0) {
      // A unit square of a grid, in any order.
      const double x = double(trial % 7), y = double(trial % 5);
      q = {Point2{x, y}, {x + 1, y}, {x, y + 1}, {x + 1, y + 1}};
      std::shuffle(q.begin(), q.end(), rng);
    } else if (trial % 4 == 1) {
      std::uniform_real_distribution<double> u(0, 1);
      for (Point2& p : q) p = {u(rng), u(rng)};
    } else {
      for (Point2& p : q) p = ring[pick(rng)];
    }
    const Side turn = Orientation(q[0], q[1], q[2]);
    if (turn == Side::kOn) continue;
    if (turn == Side::kRight) std::swap(q[1], q[2]);
    const auto same = [&](const Point2& a, const Point2& b) {
      return a.x == b.x && a.y == b.y;
    };
    if (same(q[3], q[0]) || same(q[3], q[1]) || same(q[3], q[2])) continue;
    const Kernel::Point_2 a(q[0].x, q[0].y), b(q[1].x, q[1].y),
        c(q[2].x, q[2].y), d(q[3].x, q[3].y);
    cocircular +=
        CGAL::side_of_oriented_circle(a, b, c, d) == CGAL::ON_ORIENTED_BOUNDARY;
    ASSERT_EQ(InCanonicalCircle(q[0], q[1], q[2], q[3]),
              CgalInside(q[0], q[1], q[2], q[3]))
        << "trial " << trial;
  }
  EXPECT_GT(cocircular, 5000u);
}

// Under the rule, the lexicographically largest corner of a square, (1, 1),
// is lifted most, so (0, 1) is inside the circle of (0, 0), (1, 0), (1, 1):
// the diagonal is (1, 0)-(0, 1), whatever the order of the points.
TEST(CanonicalDelaunayTest, SquareTakesTheSameDiagonalInEveryOrder) {
  EXPECT_TRUE(InCanonicalCircle({0, 0}, {1, 0}, {1, 1}, {0, 1}));
  EXPECT_FALSE(InCanonicalCircle({1, 0}, {1, 1}, {0, 1}, {0, 0}));
  std::vector<Point2> square = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  const std::set<CoordinateTriangle> expected = {{{{0, 0}, {0, 1}, {1, 0}}},
                                                 {{{0, 1}, {1, 0}, {1, 1}}}};
  std::sort(square.begin(), square.end(), [](const Point2& a, const Point2& b) {
    return std::tie(a.x, a.y) < std::tie(b.x, b.y);
  });
  int orders = 0;
  do {
    auto t = test::BuildTriangulation(test::PointsDataset(square));
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(TrianglesByCoordinates(t->mesh()), expected)
        << "order " << orders;
    BuiltMesh tiled;
    const Status s = BuildTiledMesh(square, {}, TiledBuildOptions(), &tiled);
    ASSERT_TRUE(s.ok()) << s.ToString();
    EXPECT_EQ(TrianglesByCoordinates(*tiled.mesh), expected);
    ++orders;
  } while (std::next_permutation(
      square.begin(), square.end(), [](const Point2& a, const Point2& b) {
        return std::tie(a.x, a.y) < std::tie(b.x, b.y);
      }));
  EXPECT_EQ(orders, 24);
}

TEST(CanonicalDelaunayTest,
     GridCellsAllTakeTheDiagonalFromLowerRightToUpperLeft) {
  auto t = test::BuildTriangulation(test::GridDataset(30));
  ASSERT_NE(t, nullptr);
  for (const CoordinateTriangle& tri : TrianglesByCoordinates(t->mesh())) {
    // Sorted corners: either (x, y), (x, y + 1), (x + 1, y) or
    // (x, y + 1), (x + 1, y), (x + 1, y + 1).
    const auto [x, y] = tri[0];
    const bool lower =
        tri[1] == std::pair{x, y + 1} && tri[2] == std::pair{x + 1, y};
    const bool upper =
        tri[1] == std::pair{x + 1, y - 1} && tri[2] == std::pair{x + 1, y};
    EXPECT_TRUE(lower || upper) << x << " " << y;
  }
}

// CGAL's insertion flips with the perturbed predicate, so any insertion
// order gives the canonical triangulation: no flip pass is needed after it.
TEST(CanonicalDelaunayTest, CgalBuildsAreCanonicalInEveryInsertionOrder) {
  std::mt19937_64 rng(3);
  for (Dataset dataset : {test::GridDataset(40), test::CocircularDataset(),
                          test::LinesDataset(2000, 2)}) {
    std::set<CoordinateTriangle> first;
    for (int shuffle = 0; shuffle < 6; ++shuffle) {
      std::shuffle(dataset.points.begin(), dataset.points.end(), rng);
      auto t = test::BuildTriangulation(dataset);
      ASSERT_NE(t, nullptr);
      EXPECT_EQ(CountNonCanonicalEdges(t->mesh()), 0u) << dataset.source;
      const auto triangles = TrianglesByCoordinates(t->mesh());
      if (shuffle == 0) first = triangles;
      EXPECT_EQ(triangles, first) << dataset.source << " shuffle " << shuffle;
    }
  }
}

// The check finds a square's other diagonal, and a dent in the hull.
TEST(CanonicalDelaunayTest, CountsAWrongDiagonalAndAReflexHull) {
  const auto mesh_of = [](std::vector<Point2> points,
                          std::vector<MeshTriangle> triangles,
                          std::vector<uint32_t> hull) {
    auto storage = std::make_unique<MeshVectors>();
    storage->points.assign(points.begin(), points.end());
    storage->ids = {0, 1, 2, 3};
    storage->triangles.assign(triangles.begin(), triangles.end());
    storage->hull.assign(hull.begin(), hull.end());
    ServingMesh::Arrays arrays = storage->Views();
    arrays.in_domain = static_cast<uint32_t>(arrays.triangles.size());
    arrays.input_points = 4;
    return std::make_unique<ServingMesh>(std::move(storage), arrays);
  };
  constexpr uint32_t kHull = ServingMesh::kHullBit;
  // (0,0) (1,0) (1,1) (0,1) with the diagonal 0-2 (the rule wants 1-3).
  // Triangle 0: 0 1 2 (edge 0 is 1-2, edge 1 is 2-0, edge 2 is 0-1);
  // triangle 1: 0 2 3 (edge 0 is 2-3, edge 1 is 3-0, edge 2 is 0-2).
  const auto wrong =
      mesh_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}},
              {{{0, 1, 2}, {kHull | 3, 1, kHull | 0}},
               {{0, 2, 3}, {kHull | 2, kHull | 1, 0}}},
              {ServingMesh::Edge(0, 2), ServingMesh::Edge(1, 1),
               ServingMesh::Edge(1, 0), ServingMesh::Edge(0, 0)});
  EXPECT_EQ(CountNonCanonicalEdges(*wrong), 1u);
  // The same square split the other way is canonical.
  const auto right =
      mesh_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}},
              {{{0, 1, 3}, {1, kHull | 1, kHull | 0}},
               {{1, 2, 3}, {kHull | 2, 0, kHull | 3}}},
              {ServingMesh::Edge(0, 2), ServingMesh::Edge(0, 1),
               ServingMesh::Edge(1, 0), ServingMesh::Edge(1, 2)});
  EXPECT_EQ(CountNonCanonicalEdges(*right), 0u);
  // A dart: (0,0) (1,0.5) (2,0) (1,2) as two triangles whose boundary
  // turns right at the dent (1, 0.5): not a triangulation of the hull.
  const auto dent = mesh_of({{0, 0}, {1, 0.5}, {2, 0}, {1, 2}},
                            {{{0, 1, 3}, {1, kHull | 1, kHull | 0}},
                             {{1, 2, 3}, {kHull | 2, 0, kHull | 3}}},
                            {ServingMesh::Edge(0, 2), ServingMesh::Edge(0, 1),
                             ServingMesh::Edge(1, 0), ServingMesh::Edge(1, 2)});
  EXPECT_GE(CountNonCanonicalEdges(*dent), 1u);
}

}  // namespace
}  // namespace locator
