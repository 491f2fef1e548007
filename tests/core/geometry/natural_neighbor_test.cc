#include "server/core/geometry/natural_neighbor.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/natural_neighbor_coordinates_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/mesh_walk.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using test::BuildTriangulation;
using test::GridDataset;
using test::Plane;
using test::PlaneDataset;
using test::UniformQueries;

// Weights by vertex coordinates, to compare triangulations.
using WeightMap = std::map<std::pair<double, double>, double>;

// SibsonCoordinates on t's serving mesh from the face the walk finds for q.
bool Sibson(const Triangulation& t, const Point2& q,
            std::vector<NaturalNeighbor>* out) {
  const ServingMesh& mesh = t.mesh();
  return SibsonCoordinates(mesh, Walk(mesh, mesh.DefaultStart(), q).face, q,
                           out);
}

const Point2& PointOf(const Triangulation& t, const NaturalNeighbor& n) {
  return t.mesh().arrays().points[n.vertex];
}

// The weights by their vertex's coordinates times 2^-exponent.
WeightMap ByPoint(const Triangulation& t,
                  const std::vector<NaturalNeighbor>& neighbors,
                  int exponent = 0) {
  WeightMap weights;
  for (const NaturalNeighbor& n : neighbors) {
    const Point2& p = PointOf(t, n);
    weights[{std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent)}] +=
        n.weight;
  }
  return weights;
}

// The largest weight difference, a vertex missing from one side counting
// with weight 0.
double MaxDifference(const WeightMap& a, const WeightMap& b) {
  double max = 0;
  for (const auto& [p, w] : a) {
    const auto it = b.find(p);
    max = std::max(max, std::abs(w - (it == b.end() ? 0 : it->second)));
  }
  for (const auto& [p, w] : b) {
    if (!a.contains(p)) max = std::max(max, std::abs(w));
  }
  return max;
}

double Interpolate(const Triangulation& t,
                   const std::vector<NaturalNeighbor>& neighbors) {
  double z = 0;
  for (const NaturalNeighbor& n : neighbors) {
    z += n.weight * t.mesh().arrays().values[n.vertex];
  }
  return z;
}

// Checks what holds for every q inside the hull: positive weights summing
// to 1 whose combination of the vertices is q, and (for a dataset on the
// plane) of their values is Plane(q), both to `tolerance` of the scale.
void ExpectSibsonProperties(const Triangulation& t,
                            const std::vector<NaturalNeighbor>& neighbors,
                            const Point2& q, double scale, double z_range,
                            double tolerance) {
  double sum = 0;
  Point2 combination;
  for (const NaturalNeighbor& n : neighbors) {
    EXPECT_GT(n.weight, 0) << q.x << " " << q.y;
    sum += n.weight;
    combination.x += n.weight * PointOf(t, n).x;
    combination.y += n.weight * PointOf(t, n).y;
  }
  EXPECT_NEAR(sum, 1, 1e-12) << q.x << " " << q.y;
  EXPECT_NEAR(combination.x, q.x, tolerance * scale) << q.x << " " << q.y;
  EXPECT_NEAR(combination.y, q.y, tolerance * scale) << q.x << " " << q.y;
  EXPECT_NEAR(Interpolate(t, neighbors), Plane(q), tolerance * z_range)
      << q.x << " " << q.y;
}

// CGAL's own natural_neighbor_coordinates_2 over a Delaunay_triangulation_2
// of the same points, normalised; false outside the hull.
class CgalReference {
 public:
  explicit CgalReference(const std::vector<Point2>& points) {
    for (const Point2& p : points) dt_.insert(Triangulation::ToCgal(p));
  }

  bool Weights(const Point2& q, WeightMap* out) const {
    std::vector<std::pair<Triangulation::CgalPoint, double>> coordinates;
    const auto result = CGAL::natural_neighbor_coordinates_2(
        dt_, Triangulation::ToCgal(q), std::back_inserter(coordinates));
    out->clear();
    if (!result.third) return false;
    for (const auto& [p, w] : coordinates) {
      (*out)[{p.x(), p.y()}] += w / result.second;
    }
    return true;
  }

 private:
  CGAL::Delaunay_triangulation_2<Triangulation::Kernel> dt_;
};

TEST(NaturalNeighborTest, AgreesWithCgal) {
  const Dataset dataset = PlaneDataset(500, 11);
  auto t = BuildTriangulation(dataset);
  ASSERT_NE(t, nullptr);
  const CgalReference reference(dataset.points);
  size_t inside = 0;
  double max_difference = 0;
  std::vector<NaturalNeighbor> neighbors;
  WeightMap expected;
  for (const Point2& q : UniformQueries(t->bounding_box(), 2200, 12)) {
    const bool ours = Sibson(*t, q, &neighbors);
    ASSERT_EQ(ours, reference.Weights(q, &expected)) << q.x << " " << q.y;
    if (!ours) continue;
    ++inside;
    max_difference = std::max(max_difference,
                              MaxDifference(ByPoint(*t, neighbors), expected));
  }
  EXPECT_GE(inside, 2000u);
  EXPECT_LE(max_difference, 1e-9);
}

TEST(NaturalNeighborTest, ReproducesThePlane) {
  auto t = BuildTriangulation(PlaneDataset(500, 21));
  ASSERT_NE(t, nullptr);
  std::vector<NaturalNeighbor> neighbors;
  size_t inside = 0;
  for (const Point2& q : UniformQueries(t->bounding_box(), 2000, 22)) {
    if (!Sibson(*t, q, &neighbors)) continue;
    ++inside;
    // z spans 6 over the unit square.
    ExpectSibsonProperties(*t, neighbors, q, 1, 6, 1e-9);
  }
  EXPECT_GE(inside, 1800u);
}

TEST(NaturalNeighborTest, DataPointsTakeTheirVertexOnly) {
  const Dataset dataset = PlaneDataset(300, 31);
  auto t = BuildTriangulation(dataset);
  ASSERT_NE(t, nullptr);
  std::vector<NaturalNeighbor> neighbors;
  for (size_t i = 0; i < dataset.points.size(); ++i) {
    ASSERT_TRUE(Sibson(*t, dataset.points[i], &neighbors));
    ASSERT_EQ(neighbors.size(), 1u);
    EXPECT_EQ(t->mesh().PublicId(neighbors[0].vertex),
              t->VertexOfInput(i)->info().id);
    EXPECT_EQ(neighbors[0].weight, 1);
  }
}

TEST(NaturalNeighborTest, ContinuousAcrossEdges) {
  Dataset dataset = GenerateUniform(500, 41);
  for (const Point2& p : dataset.points) {
    dataset.values.push_back(std::sin(3 * p.x) * std::cos(2 * p.y));
  }
  auto t = BuildTriangulation(dataset);
  ASSERT_NE(t, nullptr);
  const auto& dt = t->cgal();
  std::vector<NaturalNeighbor> neighbors;
  const auto value = [&](const Point2& q) {
    EXPECT_TRUE(Sibson(*t, q, &neighbors)) << q.x << " " << q.y;
    return Interpolate(*t, neighbors);
  };
  size_t edges = 0;
  size_t k = 0;
  for (const auto& [f, i] : dt.finite_edges()) {
    if (++k % 5 != 0 || t->IsInfinite(f) || t->IsInfinite(f->neighbor(i))) {
      continue;
    }
    const auto& a = f->vertex(dt.ccw(i))->point();
    const auto& b = f->vertex(dt.cw(i))->point();
    const Point2 mid{(a.x() + b.x()) / 2, (a.y() + b.y()) / 2};
    // The unit normal, times 1e-12 of the unit square.
    const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
    const double nx = -(b.y() - a.y()) / length * 1e-12;
    const double ny = (b.x() - a.x()) / length * 1e-12;
    const double at_mid = value(mid);
    // z spans at most 2.
    EXPECT_NEAR(value({mid.x + nx, mid.y + ny}), at_mid, 2e-9);
    EXPECT_NEAR(value({mid.x - nx, mid.y - ny}), at_mid, 2e-9);
    ++edges;
  }
  EXPECT_GE(edges, 200u);
}

TEST(NaturalNeighborTest, HullEdgesAreLinearAndOutsideIsRefused) {
  Dataset dataset = PlaneDataset(200, 51);
  for (const Point2 corner : {Point2{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
    dataset.points.push_back(corner);
    dataset.values.push_back(Plane(corner));
  }
  auto t = BuildTriangulation(dataset);
  ASSERT_NE(t, nullptr);
  std::vector<NaturalNeighbor> neighbors;
  for (const double s : {0.25, 0.5, 0.7, 1e-9}) {
    // Along the bottom, right, top and left sides; `s` of the way from the
    // first corner named.
    const std::pair<Point2, Point2> sides[] = {
        {{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}, {{0, 1}, {0, 0}}};
    for (const auto& [from, to] : sides) {
      const Point2 q{from.x + s * (to.x - from.x),
                     from.y + s * (to.y - from.y)};
      ASSERT_TRUE(Sibson(*t, q, &neighbors)) << q.x << " " << q.y;
      const WeightMap expected = {{{from.x, from.y}, 1 - s}, {{to.x, to.y}, s}};
      EXPECT_LE(MaxDifference(ByPoint(*t, neighbors), expected), 1e-15)
          << q.x << " " << q.y;
      ExpectSibsonProperties(*t, neighbors, q, 1, 6, 1e-15);
      // 1e-12 inside (the sides run counter-clockwise: inward is left),
      // Sibson's coordinates are near this limit (they converge linearly;
      // ~4e-10 off here), although the circumcentre of the side and the
      // point lies ~1e11 away.
      const Point2 in{q.x - 1e-12 * (to.y - from.y),
                      q.y + 1e-12 * (to.x - from.x)};
      ASSERT_TRUE(Sibson(*t, in, &neighbors)) << in.x << " " << in.y;
      EXPECT_LE(MaxDifference(ByPoint(*t, neighbors), expected), 1e-8)
          << in.x << " " << in.y;
    }
  }
  for (const Point2 q : {Point2{0.5, -1e-300},
                         {1.5, 0.5},
                         {-1, -1},
                         {0.5, 1 + 1e-15},
                         {1e300, 0.5}}) {
    neighbors.assign(1, NaturalNeighbor{0, 1});
    EXPECT_FALSE(Sibson(*t, q, &neighbors)) << q.x << " " << q.y;
    EXPECT_TRUE(neighbors.empty());
  }
}

TEST(NaturalNeighborTest, CocircularGrid) {
  Dataset dataset = GridDataset(8);
  for (const Point2& p : dataset.points) dataset.values.push_back(Plane(p));
  auto t = BuildTriangulation(dataset);
  ASSERT_NE(t, nullptr);
  const CgalReference reference(dataset.points);
  std::vector<Point2> queries = UniformQueries(t->bounding_box(), 500, 61);
  for (int y = 0; y < 7; ++y) {
    for (int x = 0; x < 7; ++x) {
      // A square's centre (on the circle through its corners), an edge's
      // midpoint, and a point on a diagonal.
      queries.push_back({x + 0.5, y + 0.5});
      queries.push_back({x + 0.5, double(y)});
      queries.push_back({x + 0.25, y + 0.25});
    }
  }
  std::vector<NaturalNeighbor> neighbors;
  WeightMap expected;
  double max_difference = 0;
  for (const Point2& q : queries) {
    ASSERT_TRUE(Sibson(*t, q, &neighbors)) << q.x << " " << q.y;
    // z spans 36 over the 7 x 7 square.
    ExpectSibsonProperties(*t, neighbors, q, 7, 36, 1e-9);
    ASSERT_TRUE(reference.Weights(q, &expected));
    max_difference = std::max(max_difference,
                              MaxDifference(ByPoint(*t, neighbors), expected));
  }
  EXPECT_LE(max_difference, 1e-9);
  // The centre of a square is equally near its four corners.
  ASSERT_TRUE(Sibson(*t, {3.5, 2.5}, &neighbors));
  EXPECT_LE(
      MaxDifference(
          ByPoint(*t, neighbors),
          {{{3, 2}, 0.25}, {{4, 2}, 0.25}, {{3, 3}, 0.25}, {{4, 3}, 0.25}}),
      1e-12);
}

// Scaling the points by a power of two changes no weight, even where the
// areas of the scaled cells would overflow or underflow a double.
TEST(NaturalNeighborTest, WeightsDoNotDependOnScale) {
  const Dataset unit = PlaneDataset(300, 71);
  auto t = BuildTriangulation(unit);
  ASSERT_NE(t, nullptr);
  const std::vector<Point2> queries =
      UniformQueries(t->bounding_box(), 300, 72);
  for (const int exponent : {-540, 540}) {
    Dataset scaled = unit;
    for (Point2& p : scaled.points) {
      p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)};
    }
    auto big = BuildTriangulation(scaled);
    ASSERT_NE(big, nullptr);
    std::vector<NaturalNeighbor> expected, neighbors;
    for (const Point2& q : queries) {
      const bool inside = Sibson(*t, q, &expected);
      ASSERT_EQ(
          Sibson(*big, {std::ldexp(q.x, exponent), std::ldexp(q.y, exponent)},
                 &neighbors),
          inside);
      if (!inside) continue;
      EXPECT_LE(MaxDifference(ByPoint(*big, neighbors, exponent),
                              ByPoint(*t, expected)),
                1e-12)
          << q.x << " " << q.y;
    }
  }
}

}  // namespace
}  // namespace locator
