// Constrained triangulations: breaklines, rings with holes, .poly segments
// with hole points and meshes served as given. Every strategy agrees with
// CGAL's locate() plus the domain flag; bad constraints are precise errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "server/core/cgal/domain_outline.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/geometry/segment_distance.h"
#include "server/core/strategies/locator_factory.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

Polyline Square(double lo, double hi) {
  return Polyline{{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}}, {}};
}

// Uniform points, a concave outer ring (a square with a notch), a square
// hole and two crossing breaklines.
Dataset TerrainDataset() {
  Dataset d = GenerateUniform(5000, 7);
  d.constraints.rings.push_back(Polyline{
      {{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.95}, {0.5, 0.7}, {0.05, 0.95}},
      {}});
  d.constraints.rings.push_back(Square(0.3, 0.45));
  d.constraints.breaklines.push_back(Polyline{{{0.1, 0.2}, {0.9, 0.3}}, {}});
  d.constraints.breaklines.push_back(Polyline{{{0.2, 0.1}, {0.25, 0.6}}, {}});
  return d;
}

// A structured grid stretched 50:1 with random diagonals: a mesh that is
// not Delaunay, served as given.
Dataset AnisotropicMesh(int k, uint64_t seed) {
  Dataset d;
  for (int y = 0; y < k; ++y) {
    for (int x = 0; x < k; ++x) d.points.push_back({x * 50.0, y * 1.0});
  }
  std::mt19937_64 random(seed);
  for (int y = 0; y + 1 < k; ++y) {
    for (int x = 0; x + 1 < k; ++x) {
      const uint32_t a = y * k + x, b = a + 1, c = a + k + 1, e = a + k;
      if (random() & 1) {
        d.constraints.triangles.push_back({a, b, c});
        d.constraints.triangles.push_back({a, c, e});
      } else {
        d.constraints.triangles.push_back({a, b, e});
        d.constraints.triangles.push_back({b, c, e});
      }
    }
  }
  return d;
}

std::unique_ptr<Triangulation> BuildOk(const Dataset& d) {
  StatusOr<std::unique_ptr<Triangulation>> t = Triangulation::Build(d);
  EXPECT_TRUE(t.ok()) << t.status().ToString();
  return t.ok() ? *std::move(t) : nullptr;
}

std::string BuildError(const Dataset& d) {
  const Status s = Triangulation::Build(d).status();
  EXPECT_FALSE(s.ok());
  return s.message();
}

// 10^4 uniform queries over the box plus the hard ones: every vertex and
// every constrained edge's midpoint (on breaklines and hole boundaries).
std::vector<Point2> HardQueries(const Triangulation& t, uint64_t seed) {
  std::vector<Point2> queries;
  const BoundingBox box = t.bounding_box().Inflated(0.05);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 10000; ++i) {
    queries.push_back({box.min_x + u(random) * box.width(),
                       box.min_y + u(random) * box.height()});
  }
  const std::vector<Point2> on_edges = test::ConstrainedEdgePoints(t);
  queries.insert(queries.end(), on_edges.begin(), on_edges.end());
  return queries;
}

void ExpectEveryStrategyAgrees(const Triangulation& t) {
  const std::vector<Point2> queries = HardQueries(t, 3);
  for (const char* name :
       {"walk", "jump-and-walk", "adaptive-paper", "self-tuning"}) {
    SCOPED_TRACE(name);
    TuningOptions options;
    options.warmup_queries = 500;
    options.retune_every = 500;
    const StatusOr<std::unique_ptr<PointLocator>> locator =
        MakePointLocator(name, t.mesh(), options);
    ASSERT_TRUE(locator.ok());
    test::ExpectAllAgree(**locator, t, queries);
  }
}

TEST(DomainTest, HoleAndConcaveBayAnswerOutsideDomain) {
  const auto t = BuildOk(TerrainDataset());
  ASSERT_TRUE(t);
  EXPECT_TRUE(t->has_domain());
  EXPECT_EQ(t->num_holes(), 1u);
  EXPECT_LT(t->num_triangles(), t->num_faces());
  for (const Point2 q : {Point2{0.37, 0.37}, Point2{0.5, 0.85}}) {
    const LocateResult r = t->ReferenceLocate(q);
    EXPECT_EQ(r.type, LocationType::kOutsideDomain) << q.x << " " << q.y;
    EXPECT_EQ(r.triangle_id, -1);
    EXPECT_FALSE(r.has_value);
    EXPECT_GE(r.domain_edge_ids[0], 0);
  }
  // On the hole's boundary the point is in the domain (closed triangles).
  EXPECT_EQ(t->ReferenceLocate({0.3, 0.4}).type, LocationType::kEdge);
  EXPECT_EQ(t->ReferenceLocate({0.3, 0.3}).type, LocationType::kVertex);
  EXPECT_EQ(t->ReferenceLocate({0.6, 0.5}).type, LocationType::kFace);
}

TEST(DomainTest, NearestBoundaryEdgeOfTheHole) {
  Dataset d = test::GridDataset(11);  // 0..10
  d.constraints.rings.push_back(Square(0, 10));
  d.constraints.rings.push_back(Square(3, 7));
  const auto t = BuildOk(d);
  ASSERT_TRUE(t);
  const LocateResult r = t->ReferenceLocate({3.2, 5.5});
  ASSERT_EQ(r.type, LocationType::kOutsideDomain);
  // The hole's left side x = 3 runs through grid points 3 + 11y; the
  // nearest piece is (3, 5)-(3, 6).
  std::array<int64_t, 2> edge = r.domain_edge_ids;
  std::sort(edge.begin(), edge.end());
  EXPECT_EQ(edge, (std::array<int64_t, 2>{3 + 11 * 5, 3 + 11 * 6}));
}

TEST(DomainTest, EveryStrategyAgreesOnConstrainedTerrain) {
  const auto t = BuildOk(TerrainDataset());
  ASSERT_TRUE(t);
  ExpectEveryStrategyAgrees(*t);
}

TEST(DomainTest, EveryStrategyAgreesOnAnisotropicMesh) {
  const Dataset d = AnisotropicMesh(60, 5);
  const auto t = BuildOk(d);
  ASSERT_TRUE(t);
  // Served as given: exactly the given triangles, in the domain.
  EXPECT_EQ(t->num_triangles(), d.constraints.triangles.size());
  for (const auto& tri : d.constraints.triangles) {
    Triangulation::Face_handle f;
    const bool ccw =
        CGAL::orientation(Triangulation::ToCgal(d.points[tri[0]]),
                          Triangulation::ToCgal(d.points[tri[1]]),
                          Triangulation::ToCgal(d.points[tri[2]])) ==
        CGAL::COUNTERCLOCKWISE;
    const std::array<uint32_t, 3> ids =
        ccw ? tri : std::array<uint32_t, 3>{tri[0], tri[2], tri[1]};
    ASSERT_TRUE(t->FaceWithCorners(ids, &f));
    EXPECT_TRUE(t->InDomain(f));
  }
  ExpectEveryStrategyAgrees(*t);
}

TEST(DomainTest, PolySegmentsWithHolePoint) {
  Dataset d = GenerateUniform(2000, 9);
  d.constraints.segments.push_back(Square(0.1, 0.9));
  d.constraints.segments.back().points.push_back({0.1, 0.1});
  d.constraints.segments.push_back(Square(0.4, 0.6));
  d.constraints.segments.back().points.push_back({0.4, 0.4});
  d.constraints.hole_seeds.push_back({0.5, 0.5});
  const auto t = BuildOk(d);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->num_holes(), 1u);
  EXPECT_EQ(t->ReferenceLocate({0.5, 0.5}).type, LocationType::kOutsideDomain);
  EXPECT_EQ(t->ReferenceLocate({0.05, 0.5}).type, LocationType::kOutsideDomain);
  EXPECT_EQ(t->ReferenceLocate({0.2, 0.5}).type, LocationType::kFace);
  ExpectEveryStrategyAgrees(*t);
}

TEST(DomainTest, PolyFileHoleNeverAnswersAValue) {
  const StatusOr<Dataset> d = ParsePolyText(
      "8 2 1 0\n"
      "0 0 0 10\n1 4 0 10\n2 4 4 10\n3 0 4 10\n"
      "4 1 1 20\n5 3 1 20\n6 3 3 20\n7 1 3 20\n"
      "8 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 7\n7 7 4\n"
      "1\n0 2 2\n",
      "terrain.poly");
  ASSERT_TRUE(d.ok()) << d.status().ToString();
  const auto t = BuildOk(*d);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->num_holes(), 1u);
  EXPECT_EQ(t->num_triangles(), 8u);  // the ring between the squares
  for (const Point2 q : {Point2{2, 2}, Point2{1.5, 2.9}}) {
    const LocateResult r = t->ReferenceLocate(q);
    EXPECT_EQ(r.type, LocationType::kOutsideDomain);
    EXPECT_FALSE(r.has_value);
  }
  const LocateResult on_hole_edge = t->ReferenceLocate({2, 1});
  EXPECT_EQ(on_hole_edge.type, LocationType::kEdge);
  EXPECT_DOUBLE_EQ(on_hole_edge.value, 20);
  const LocateResult inside = t->ReferenceLocate({0.5, 2});
  EXPECT_EQ(inside.type, LocationType::kFace);
  EXPECT_DOUBLE_EQ(inside.value, 15);
}

TEST(DomainTest, DigestCoversTheConstraints) {
  const Dataset plain = GenerateUniform(500, 2);
  Dataset with_hole = plain;
  with_hole.constraints.rings = {Square(0.1, 0.9), Square(0.4, 0.6)};
  Dataset other_hole = plain;
  other_hole.constraints.rings = {Square(0.1, 0.9), Square(0.3, 0.6)};
  const auto a = BuildOk(plain);
  const auto b = BuildOk(with_hole);
  const auto b_again = BuildOk(with_hole);
  const auto c = BuildOk(other_hole);
  ASSERT_TRUE(a && b && b_again && c);
  EXPECT_NE(a->VertexDigest(), b->VertexDigest());
  EXPECT_NE(b->VertexDigest(), c->VertexDigest());
  EXPECT_EQ(b->VertexDigest(), b_again->VertexDigest());
}

TEST(DomainTest, ValuesAreNeverInterpolatedAcrossABreakline) {
  Dataset d = test::PlaneDataset(3000, 4);
  // A breakline whose z (100) is far from the plane (z < 6): a triangle
  // crossing it would blend the two.
  d.constraints.breaklines.push_back(
      Polyline{{{0.2, 0.5}, {0.8, 0.5}}, {100, 100}});
  const auto t = BuildOk(d);
  ASSERT_TRUE(t);
  for (double x = 0.25; x < 0.8; x += 0.05) {
    const LocateResult on = t->ReferenceLocate({x, 0.5});
    ASSERT_NE(on.type, LocationType::kFace) << x;
    EXPECT_DOUBLE_EQ(on.value, 100) << x;
    // Just beside it, the triangle has the breakline as an edge.
    const LocateResult beside = t->ReferenceLocate({x, 0.5 + 1e-9});
    EXPECT_NEAR(beside.value, 100, 1e-3) << x;
  }
}

TEST(DomainTest, CrossingBreaklinesGetAnInterpolatedVertex) {
  Dataset d = test::PlaneDataset(1000, 4);
  d.constraints.breaklines.push_back(
      Polyline{{{0.25, 0.25}, {0.75, 0.75}}, {0, 10}});
  d.constraints.breaklines.push_back(
      Polyline{{{0.25, 0.75}, {0.75, 0.25}}, {20, 20}});
  const auto t = BuildOk(d);
  ASSERT_TRUE(t);
  const LocateResult r = t->ReferenceLocate({0.5, 0.5});
  ASSERT_EQ(r.type, LocationType::kVertex);
  // 4 breakline points after the 1000 input points, then the crossing.
  EXPECT_EQ(r.vertex_ids[r.feature_index], 1004);
  EXPECT_DOUBLE_EQ(r.value, 5);  // along the first breakline
}

// Total length of `segments`.
double Length(const std::vector<std::array<Point2, 2>>& segments) {
  double length = 0;
  for (const auto& [a, b] : segments)
    length += std::hypot(b.x - a.x, b.y - a.y);
  return length;
}

// Whether every segment lies on one of `lines`: both ends within 1e-12 of
// it (a crossing of two breaklines is rounded to doubles).
bool AllOn(const std::vector<std::array<Point2, 2>>& segments,
           const std::vector<std::array<Point2, 2>>& lines) {
  const auto on = [](const std::array<Point2, 2>& line, const Point2& p) {
    return SegmentDistance2(line[0], line[1], p) <= 1e-24;
  };
  return std::all_of(segments.begin(), segments.end(), [&](const auto& s) {
    return std::any_of(lines.begin(), lines.end(), [&](const auto& line) {
      return on(line, s[0]) && on(line, s[1]);
    });
  });
}

// The segments of `lines`, closing each one if `closed`.
std::vector<std::array<Point2, 2>> SegmentsOf(
    const std::vector<Polyline>& lines, bool closed) {
  std::vector<std::array<Point2, 2>> segments;
  for (const Polyline& line : lines) {
    const size_t n = line.points.size();
    for (size_t k = 0; k + (closed ? 0 : 1) < n; ++k) {
      segments.push_back({line.points[k], line.points[(k + 1) % n]});
    }
  }
  return segments;
}

TEST(DomainTest, OutlineIsTheBoundaryAndTheBreaklines) {
  const Dataset d = TerrainDataset();
  const auto t = BuildOk(d);
  ASSERT_TRUE(t);
  const DomainOutline outline = OutlineOf(*t, 100'000);
  const auto rings = SegmentsOf(d.constraints.rings, true);
  const auto breaklines = SegmentsOf(d.constraints.breaklines, false);
  EXPECT_TRUE(AllOn(outline.boundary, rings));
  EXPECT_TRUE(AllOn(outline.breaklines, breaklines));
  // All of both, once: the pieces add up to the rings and the breaklines.
  EXPECT_NEAR(Length(outline.boundary), Length(rings), 1e-12);
  EXPECT_NEAR(Length(outline.breaklines), Length(breaklines), 1e-12);

  // Thinned evenly to the bound.
  const DomainOutline thin = OutlineOf(*t, 10);
  EXPECT_LE(thin.boundary.size(), 10u);
  EXPECT_GE(thin.boundary.size(), 5u);
  EXPECT_EQ(thin.boundary.front()[0].x, outline.boundary.front()[0].x);
  EXPECT_EQ(thin.boundary.front()[1].y, outline.boundary.front()[1].y);
}

TEST(DomainTest, MeshOutlineIsItsHullAndPlainPointsHaveNone) {
  const auto mesh = BuildOk(AnisotropicMesh(10, 3));
  ASSERT_TRUE(mesh);
  const DomainOutline outline = OutlineOf(*mesh, 100'000);
  // A mesh's own edges are not breaklines; its boundary is the 450 x 9 box.
  EXPECT_TRUE(outline.breaklines.empty());
  EXPECT_DOUBLE_EQ(Length(outline.boundary), 2 * (450 + 9));

  const auto plain = BuildOk(GenerateUniform(500, 3));
  ASSERT_TRUE(plain);
  const DomainOutline none = OutlineOf(*plain, 100'000);
  EXPECT_TRUE(none.boundary.empty());
  EXPECT_TRUE(none.breaklines.empty());
}

TEST(DomainTest, BadConstraintsArePreciseErrors) {
  Dataset bowtie = GenerateUniform(100, 1);
  bowtie.constraints.rings.push_back(
      Polyline{{{0.1, 0.1}, {0.9, 0.9}, {0.9, 0.1}, {0.1, 0.9}}, {}});
  EXPECT_NE(BuildError(bowtie).find("cross at (0.5, 0.5)"), std::string::npos);

  // The same bow-tie crossing at a dataset point: still a crossing.
  Dataset bowtie_at_point = bowtie;
  bowtie_at_point.points.push_back({0.5, 0.5});
  EXPECT_NE(BuildError(bowtie_at_point)
                .find("ring 0 segment 0 and ring 0 segment 2 cross at "
                      "(0.5, 0.5): a domain boundary must not intersect "
                      "itself"),
            std::string::npos)
      << BuildError(bowtie_at_point);
  // Two rings touching at a corner are fine (a hole may touch its shell).
  Dataset touching = GenerateUniform(100, 1);
  touching.constraints.rings.push_back(Square(0.1, 0.9));
  touching.constraints.rings.push_back(
      Polyline{{{0.1, 0.1}, {0.5, 0.3}, {0.3, 0.5}}, {}});
  EXPECT_TRUE(BuildOk(touching));

  Dataset seed_outside = GenerateUniform(100, 1);
  seed_outside.constraints.rings.push_back(Square(0.2, 0.4));
  seed_outside.constraints.hole_seeds.push_back({0.7, 0.7});
  EXPECT_NE(BuildError(seed_outside).find("hole point 0"), std::string::npos);

  Dataset empty = GenerateUniform(100, 1);
  empty.constraints.segments.push_back(Square(0.2, 0.4));
  empty.constraints.segments.back().points.push_back({0.2, 0.2});
  empty.constraints.hole_seeds.push_back({0.3, 0.3});
  EXPECT_NE(BuildError(empty).find("the domain is empty"), std::string::npos);

  Dataset mesh = AnisotropicMesh(3, 1);
  mesh.constraints.triangles.push_back({0, 1, 99});
  EXPECT_NE(BuildError(mesh).find("mesh triangle 8 (0 1 99): corner index 99 "
                                  "is out of range"),
            std::string::npos);
  mesh = AnisotropicMesh(3, 1);
  mesh.constraints.triangles.push_back({0, 0, 1});
  EXPECT_NE(BuildError(mesh).find("repeated corners"), std::string::npos);
  mesh = AnisotropicMesh(3, 1);
  mesh.constraints.triangles.push_back({0, 1, 2});
  EXPECT_NE(BuildError(mesh).find("collinear corners"), std::string::npos);

  // Three triangles on the edge (0, 1).
  Dataset fan;
  fan.points = {{0, 0}, {1, 0}, {0.5, 1}, {0.5, -1}, {0.5, 2}};
  fan.constraints.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 1, 4}};
  EXPECT_NE(BuildError(fan).find("mesh edge (0 1) is shared by triangles 0, "
                                 "1 and 2"),
            std::string::npos);

  Dataset overlap;
  overlap.points = {{0, 0}, {2, 0}, {0, 2}, {1, -1}, {1, 3}, {3, 3}};
  overlap.constraints.triangles = {{0, 1, 2}, {3, 5, 4}};
  EXPECT_NE(BuildError(overlap).find("the mesh's triangles overlap"),
            std::string::npos);
}

}  // namespace
}  // namespace locator
