// TraceProfile: the crossings against a brute force over every edge, exact
// degeneracies on the integer grid (lines through vertices and along
// edges), gaps outside the hull and in a hole, samples against
// ReferenceLocate, limits and bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "server/core/cgal/triangulation.h"
#include "server/core/geometry/barycentric.h"
#include "server/core/geometry/segment_distance.h"
#include "server/core/surface/profile_trace.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using Face_handle = Triangulation::Face_handle;
using Kind = ProfilePointKind;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Polyline Square(double lo, double hi) {
  return Polyline{{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}}, {}};
}

// A square ring whose corners (not dataset points) have the value 0.5.
Polyline ValuedSquare(double lo, double hi) {
  Polyline ring = Square(lo, hi);
  ring.values.assign(ring.points.size(), 0.5);
  return ring;
}

// `dataset` with values uniform in [0, 1] instead of its own.
Dataset WithRandomValues(Dataset dataset, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1);
  dataset.values.clear();
  for (size_t i = 0; i < dataset.points.size(); ++i) {
    dataset.values.push_back(u(random));
  }
  return dataset;
}

Dataset PlaneGrid(int k) {
  Dataset d = test::GridDataset(k);
  for (const Point2& p : d.points) d.values.push_back(test::Plane(p));
  return d;
}

Profile Trace(const Triangulation& t, const std::vector<Point2>& line,
              const ProfileOptions& options = ProfileOptions()) {
  Profile profile;
  const Status s =
      TraceProfile(t.mesh(), t.mesh().DefaultStart(), line, options, &profile);
  EXPECT_TRUE(s.ok()) << s.ToString();
  return profile;
}

double Distance(const Point2& a, const Point2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

Point2 Cgal(const Triangulation::CgalPoint& p) {
  return Triangulation::FromCgal(p);
}

// The piecewise-linear value at q from the triangle f (q in or near it).
double LinearValueIn(Face_handle f, const Point2& q) {
  const auto b =
      Barycentric(Cgal(f->vertex(0)->point()), Cgal(f->vertex(1)->point()),
                  Cgal(f->vertex(2)->point()), q);
  double value = 0;
  for (int i = 0; i < 3; ++i) value += b[i] * f->vertex(i)->info().value;
  return value;
}

std::map<int64_t, Face_handle> FacesById(const Triangulation& t) {
  std::map<int64_t, Face_handle> faces;
  for (Face_handle f : t.cgal().finite_face_handles()) {
    if (t.InDomain(f)) faces[f->info()] = f;
  }
  return faces;
}

std::vector<ProfilePoint> OfKind(const Profile& profile, Kind kind) {
  std::vector<ProfilePoint> points;
  for (const ProfilePoint& p : profile.breakpoints) {
    if (p.kind == kind) points.push_back(p);
  }
  return points;
}

// Invariants of every profile of a one-segment line p->q: distances are
// non-decreasing and equal |point - p|; the triangle named after a
// breakpoint holds the stretch up to the next one.
void ExpectConsistent(const Triangulation& t, const Profile& profile,
                      const Point2& p) {
  const auto faces = FacesById(t);
  const auto& points = profile.breakpoints;
  for (size_t i = 0; i < points.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(points[i].distance, Distance(points[i].point, p), 1e-9);
    if (i == 0) continue;
    EXPECT_GE(points[i].distance, points[i - 1].distance);
    if (points[i - 1].triangle_id < 0) continue;
    const Point2 mid{(points[i - 1].point.x + points[i].point.x) / 2,
                     (points[i - 1].point.y + points[i].point.y) / 2};
    const Face_handle f = faces.at(points[i - 1].triangle_id);
    const auto b =
        Barycentric(Cgal(f->vertex(0)->point()), Cgal(f->vertex(1)->point()),
                    Cgal(f->vertex(2)->point()), mid);
    for (double c : b) EXPECT_GE(c, -1e-9);
  }
}

// A finite in-domain face on either side of the edge (f, i); null if none.
Face_handle BesideInDomain(const Triangulation& t, Face_handle f, int i) {
  for (Face_handle g : {f, f->neighbor(i)}) {
    if (!t.IsInfinite(g) && t.InDomain(g)) return g;
  }
  return Face_handle();
}

struct Crossed {
  double t;
  Face_handle face;
  int edge;
};

// Every finite edge with the surface on a side whose interior the interior of
// p->q crosses, counted exactly, in order along the segment; *vertices_passed
// counts the mesh vertices strictly between p and q.
std::vector<Crossed> BruteForceCrossings(const Triangulation& t,
                                         const Point2& p, const Point2& q,
                                         size_t* vertices_passed) {
  const auto cp = Triangulation::ToCgal(p);
  const auto cq = Triangulation::ToCgal(q);
  *vertices_passed = 0;
  for (auto v : t.cgal().finite_vertex_handles()) {
    if (CGAL::orientation(cp, cq, v->point()) == CGAL::ZERO &&
        CGAL::compare_xy(cp, v->point()) == CGAL::compare_xy(v->point(), cq)) {
      ++*vertices_passed;
    }
  }
  std::vector<Crossed> crossed;
  for (const auto& [f, i] : t.cgal().finite_edges()) {
    if (BesideInDomain(t, f, i) == Face_handle()) continue;
    const auto& a = f->vertex(Triangulation::Cdt::ccw(i))->point();
    const auto& b = f->vertex(Triangulation::Cdt::cw(i))->point();
    if (CGAL::orientation(cp, cq, a) * CGAL::orientation(cp, cq, b) < 0 &&
        CGAL::orientation(a, b, cp) * CGAL::orientation(a, b, cq) < 0) {
      const Point2 pa = Cgal(a), pb = Cgal(b);
      const double da = (q.x - p.x) * (pa.y - p.y) - (q.y - p.y) * (pa.x - p.x);
      const double db = (q.x - p.x) * (pb.y - p.y) - (q.y - p.y) * (pb.x - p.x);
      const double s = da / (da - db);
      const Point2 x{pa.x + s * (pb.x - pa.x), pa.y + s * (pb.y - pa.y)};
      crossed.push_back({Distance(x, p), f, i});
    }
  }
  std::sort(crossed.begin(), crossed.end(),
            [](const Crossed& x, const Crossed& y) { return x.t < y.t; });
  return crossed;
}

// The edge crossings of p->q on t are exactly the brute force's, in order:
// on that edge, with the linear value of a triangle beside it.
void ExpectCrossingsMatchBruteForce(const Triangulation& t, const Point2& p,
                                    const Point2& q) {
  SCOPED_TRACE(testing::Message() << "(" << p.x << ", " << p.y << ") -> ("
                                  << q.x << ", " << q.y << ")");
  const Profile profile = Trace(t, {p, q});
  ExpectConsistent(t, profile, p);
  size_t vertices_passed = 0;
  const std::vector<Crossed> expected =
      BruteForceCrossings(t, p, q, &vertices_passed);
  EXPECT_EQ(OfKind(profile, Kind::kMeshVertex).size(), vertices_passed);
  const std::vector<ProfilePoint> got = OfKind(profile, Kind::kEdgeCrossing);
  ASSERT_EQ(got.size(), expected.size());
  EXPECT_EQ(profile.crossings, expected.size() + vertices_passed);
  for (size_t k = 0; k < got.size(); ++k) {
    SCOPED_TRACE(k);
    const Face_handle f = expected[k].face;
    const int i = expected[k].edge;
    const Point2 a = Cgal(f->vertex(Triangulation::Cdt::ccw(i))->point());
    const Point2 b = Cgal(f->vertex(Triangulation::Cdt::cw(i))->point());
    EXPECT_LT(
        std::sqrt(static_cast<double>(SegmentDistance2(a, b, got[k].point))),
        1e-9);
    ASSERT_TRUE(got[k].has_value);
    EXPECT_NEAR(got[k].value,
                LinearValueIn(BesideInDomain(t, f, i), got[k].point), 1e-9);
  }
}

TEST(ProfileTest, CrossingsMatchBruteForceOnRandomDelaunay) {
  const auto t =
      test::BuildTriangulation(WithRandomValues(test::PlaneDataset(200, 5), 6));
  ASSERT_NE(t, nullptr);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  for (int i = 0; i < 200; ++i) {
    const Point2 p{u(random), u(random)};
    const Point2 q{u(random), u(random)};
    ExpectCrossingsMatchBruteForce(*t, p, q);
    // Outside the hull at p: the line starts in a gap.
    if (t->ReferenceLocate(p).type == LocationType::kOutsideConvexHull) {
      const Profile profile = Trace(*t, {p, q});
      ASSERT_FALSE(profile.gaps.empty());
      EXPECT_EQ(profile.gaps[0].from_distance, 0);
      EXPECT_EQ(profile.gaps[0].reason, LocationType::kOutsideConvexHull);
    }
  }
}

TEST(ProfileTest, CrossingsMatchBruteForceWithConstraints) {
  // A concave outer ring, a hole and two crossing breaklines: crossings
  // between two faces outside the domain are not reported.
  Dataset d = WithRandomValues(GenerateUniform(300, 15), 16);
  d.constraints.rings = {
      Polyline{
          {{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.95}, {0.5, 0.7}, {0.05, 0.95}},
          std::vector<double>(5, 0.5)},
      ValuedSquare(0.3, 0.45)};
  d.constraints.breaklines = {Polyline{{{0.1, 0.2}, {0.9, 0.3}}, {0, 1}},
                              Polyline{{{0.2, 0.1}, {0.25, 0.6}}, {1, 0}}};
  const auto t = test::BuildTriangulation(d);
  ASSERT_NE(t, nullptr);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  for (int i = 0; i < 200; ++i) {
    ExpectCrossingsMatchBruteForce(*t, {u(random), u(random)},
                                   {u(random), u(random)});
  }
}

TEST(ProfileTest, ReproducesAPlane) {
  const auto t = test::BuildTriangulation(test::PlaneDataset(500, 3));
  ASSERT_NE(t, nullptr);
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> u(0, 1);
  ProfileOptions options;
  options.samples = 33;
  for (int i = 0; i < 50; ++i) {
    const std::vector<Point2> line = {
        {u(random), u(random)}, {u(random), u(random)}, {u(random), u(random)}};
    const Profile profile = Trace(*t, line, options);
    size_t with_value = 0;
    for (const auto* points : {&profile.breakpoints, &profile.samples}) {
      for (const ProfilePoint& p : *points) {
        if (!p.has_value) continue;
        ++with_value;
        EXPECT_NEAR(p.value, test::Plane(p.point), 1e-9);
      }
    }
    EXPECT_GT(with_value, profile.breakpoints.size() / 2);
  }
}

TEST(ProfileTest, GridLinesThroughVerticesAndAlongEdges) {
  const auto t = test::BuildTriangulation(PlaneGrid(9));
  ASSERT_NE(t, nullptr);
  // The diagonal passes every (i, i); a cell diagonal the other way is
  // crossed at the cell's centre.
  Profile diagonal = Trace(*t, {{0, 0}, {8, 8}});
  const auto vertices = OfKind(diagonal, Kind::kMeshVertex);
  ASSERT_EQ(vertices.size(), 7u);
  for (int i = 1; i <= 7; ++i) {
    EXPECT_EQ(vertices[i - 1].point.x, i);
    EXPECT_EQ(vertices[i - 1].point.y, i);
    EXPECT_NEAR(vertices[i - 1].distance, i * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(vertices[i - 1].value, test::Plane({1.0 * i, 1.0 * i}), 1e-9);
  }
  for (const ProfilePoint& p : OfKind(diagonal, Kind::kEdgeCrossing)) {
    EXPECT_EQ(p.point.x - std::floor(p.point.x), 0.5);
    EXPECT_EQ(p.point.y, p.point.x);
  }
  // Along a row, both ways, from a grid point or from an edge's middle:
  // only mesh vertices.
  for (const auto& [p, q, passed] :
       {std::tuple{Point2{0, 3}, Point2{8, 3}, size_t{7}},
        std::tuple{Point2{8, 3}, Point2{0, 3}, size_t{7}},
        std::tuple{Point2{0.5, 3}, Point2{7.5, 3}, size_t{7}},
        std::tuple{Point2{5, 0.5}, Point2{5, 2}, size_t{1}}}) {
    const Profile row = Trace(*t, {p, q});
    EXPECT_EQ(OfKind(row, Kind::kEdgeCrossing).size(), 0u);
    EXPECT_EQ(OfKind(row, Kind::kMeshVertex).size(), passed);
    for (const ProfilePoint& b : row.breakpoints) {
      EXPECT_NEAR(b.value, test::Plane(b.point), 1e-9);
      EXPECT_GE(b.triangle_id, 0);
    }
    EXPECT_TRUE(row.gaps.empty());
  }
  // Random segments between half-integer points: every degeneracy at once.
  std::mt19937_64 random(8);
  std::uniform_int_distribution<int> half(0, 16);
  for (int i = 0; i < 300; ++i) {
    const Point2 p{half(random) / 2.0, half(random) / 2.0};
    const Point2 q{half(random) / 2.0, half(random) / 2.0};
    if (p.x == q.x && p.y == q.y) continue;
    ExpectCrossingsMatchBruteForce(*t, p, q);
  }
}

TEST(ProfileTest, GapsOutsideTheHull) {
  // The hull is the square [0, 4]^2.
  const auto t = test::BuildTriangulation(PlaneGrid(5));
  ASSERT_NE(t, nullptr);
  const auto expect_gaps =
      [&](const std::vector<Point2>& line,
          const std::vector<std::pair<double, double>>& expected) {
        SCOPED_TRACE(testing::Message()
                     << "from (" << line[0].x << ", " << line[0].y << ")");
        const Profile profile = Trace(*t, line);
        EXPECT_EQ(profile.gaps.size(), expected.size());
        for (size_t i = 0; i < std::min(expected.size(), profile.gaps.size());
             ++i) {
          EXPECT_NEAR(profile.gaps[i].from_distance, expected[i].first, 1e-12);
          EXPECT_NEAR(profile.gaps[i].to_distance, expected[i].second, 1e-12);
          EXPECT_EQ(profile.gaps[i].reason, LocationType::kOutsideConvexHull);
        }
        for (const ProfilePoint& p : profile.breakpoints) {
          const bool inside = p.point.x >= 0 && p.point.x <= 4 &&
                              p.point.y >= 0 && p.point.y <= 4;
          EXPECT_EQ(p.has_value, inside) << p.point.x << " " << p.point.y;
          if (p.has_value) {
            EXPECT_NEAR(p.value, test::Plane(p.point), 1e-9);
          }
        }
        return profile;
      };
  // Across: in at x = 0, out at x = 4.
  const Profile across = expect_gaps({{-2, 1.5}, {6, 1.5}}, {{0, 2}, {6, 8}});
  const auto& points = across.breakpoints;
  // 2 line vertices, 5 vertical edges, 4 cell diagonals.
  ASSERT_EQ(points.size(), 11u);
  EXPECT_EQ(points[0].triangle_id, -1);
  EXPECT_GE(points[1].triangle_id, 0);
  EXPECT_EQ(points[1].point.x, 0);
  EXPECT_EQ(points[9].point.x, 4);
  EXPECT_EQ(points[9].triangle_id, -1);  // a gap begins
  EXPECT_EQ(points[10].triangle_id, -1);
  // Entirely outside, and only touching the corner (0, 0): one gap.
  const Profile outside = expect_gaps({{-3, -1}, {5, -1}}, {{0, 8}});
  EXPECT_EQ(outside.breakpoints.size(), 2u);
  EXPECT_EQ(outside.crossings, 0u);
  const Profile touching =
      expect_gaps({{-1, 1}, {1, -1}}, {{0, 2 * std::sqrt(2.0)}});
  EXPECT_EQ(touching.crossings, 0u);
  // Along the hull's bottom edge; through two opposite corners.
  const Profile along = expect_gaps({{-2, 0}, {6, 0}}, {{0, 2}, {6, 8}});
  EXPECT_EQ(OfKind(along, Kind::kMeshVertex).size(), 5u);
  EXPECT_EQ(OfKind(along, Kind::kEdgeCrossing).size(), 0u);
  const double r2 = std::sqrt(2.0);
  const Profile corners =
      expect_gaps({{-1, -1}, {5, 5}}, {{0, r2}, {5 * r2, 6 * r2}});
  EXPECT_EQ(OfKind(corners, Kind::kMeshVertex).size(), 5u);
  // Starting inside and ending outside, and ending on the hull.
  expect_gaps({{2.5, 2}, {2.5, 7}}, {{2, 5}});
  expect_gaps({{-2.5, 2}, {0, 2}}, {{0, 2.5}});
  // A polyline that leaves and comes back: segment 1 is all outside.
  const Profile bend = expect_gaps({{1, 1}, {6, 1}, {6, 3}, {1, 3}}, {{3, 9}});
  const auto bends = OfKind(bend, Kind::kLineVertex);
  ASSERT_EQ(bends.size(), 4u);
  for (uint32_t i = 0; i < 4; ++i) EXPECT_EQ(bends[i].segment, std::min(i, 2u));
  EXPECT_NEAR(bend.length, 12, 1e-12);
}

TEST(ProfileTest, HoleIsAnOutsideDomainGap) {
  Dataset d = PlaneGrid(11);  // 0..10
  d.constraints.rings = {Square(0, 10), Square(3, 7)};
  const auto t = test::BuildTriangulation(d);
  ASSERT_NE(t, nullptr);
  const double r2 = std::sqrt(2.0);
  for (const auto& [p, q, from, to] :
       {std::tuple{Point2{1, 5.5}, Point2{9, 5.5}, 2.0, 6.0},
        std::tuple{Point2{9, 5.5}, Point2{1, 5.5}, 2.0, 6.0},
        std::tuple{Point2{1, 1}, Point2{9, 9}, 2 * r2, 6 * r2}}) {
    SCOPED_TRACE(testing::Message() << p.x << " " << p.y);
    const Profile profile = Trace(*t, {p, q});
    ASSERT_EQ(profile.gaps.size(), 1u);
    EXPECT_EQ(profile.gaps[0].reason, LocationType::kOutsideDomain);
    EXPECT_NEAR(profile.gaps[0].from_distance, from, 1e-12);
    EXPECT_NEAR(profile.gaps[0].to_distance, to, 1e-12);
    for (const ProfilePoint& b : profile.breakpoints) {
      EXPECT_FALSE(b.point.x > 3 && b.point.x < 7 && b.point.y > 3 &&
                   b.point.y < 7)
          << "inside the hole: " << b.point.x << " " << b.point.y;
      EXPECT_TRUE(b.has_value);
      EXPECT_NEAR(b.value, test::Plane(b.point), 1e-9);
      // Only where the gap begins is no triangle ahead.
      EXPECT_EQ(b.triangle_id < 0, b.distance == profile.gaps[0].from_distance);
    }
  }
  // Along the hole's side: on the closed domain all the way.
  const Profile side = Trace(*t, {{3, 1}, {3, 9}});
  EXPECT_TRUE(side.gaps.empty());
  EXPECT_EQ(OfKind(side, Kind::kMeshVertex).size(), 7u);

  // Random points, a ring inside the hull and a hole: three gaps.
  Dataset uniform = WithRandomValues(GenerateUniform(2000, 5), 9);
  uniform.constraints.rings = {ValuedSquare(0.1, 0.9), ValuedSquare(0.4, 0.6)};
  const auto u = test::BuildTriangulation(uniform);
  ASSERT_NE(u, nullptr);
  const Profile profile = Trace(*u, {{0.05, 0.5}, {0.95, 0.5}});
  const double expected[3][2] = {{0, 0.05}, {0.35, 0.55}, {0.85, 0.9}};
  ASSERT_EQ(profile.gaps.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(profile.gaps[i].reason, LocationType::kOutsideDomain);
    EXPECT_NEAR(profile.gaps[i].from_distance, expected[i][0], 1e-12);
    EXPECT_NEAR(profile.gaps[i].to_distance, expected[i][1], 1e-12);
  }
  for (const ProfilePoint& b : profile.breakpoints) {
    EXPECT_FALSE(b.point.x > 0.4 + 1e-12 && b.point.x < 0.6 - 1e-12);
    if (std::abs(b.point.x - 0.4) < 1e-12 ||
        std::abs(b.point.x - 0.6) < 1e-12) {
      EXPECT_TRUE(b.has_value);
      EXPECT_NEAR(b.value, u->ReferenceLocate(b.point).value, 1e-9);
    }
  }
}

// The point at `distance` along the polyline.
Point2 PointAlong(const std::vector<Point2>& line, double distance) {
  for (size_t s = 0; s + 1 < line.size(); ++s) {
    const double length = Distance(line[s], line[s + 1]);
    if (distance <= length || s + 2 == line.size()) {
      const double f = length > 0 ? std::min(distance / length, 1.0) : 0;
      return {line[s].x + f * (line[s + 1].x - line[s].x),
              line[s].y + f * (line[s + 1].y - line[s].y)};
    }
    distance -= length;
  }
  return line.back();
}

TEST(ProfileTest, SamplesMatchReferenceLocate) {
  Dataset d = WithRandomValues(GenerateUniform(3000, 12), 13);
  d.constraints.rings = {ValuedSquare(0.05, 0.95), ValuedSquare(0.45, 0.65)};
  const auto t = test::BuildTriangulation(d);
  ASSERT_NE(t, nullptr);
  const std::vector<Point2> line = {
      {-0.1, 0.2}, {0.7, 0.8}, {0.9, 0.1}, {0.9, 0.1}, {0.3, 0.5}};
  ProfileOptions options;
  options.samples = 57;
  const Profile profile = Trace(*t, line, options);
  ASSERT_EQ(profile.samples.size(), 57u);
  size_t with_value = 0;
  for (uint32_t i = 0; i < 57; ++i) {
    SCOPED_TRACE(i);
    const ProfilePoint& s = profile.samples[i];
    EXPECT_EQ(s.kind, Kind::kSample);
    EXPECT_NEAR(s.distance, profile.length * i / 56, 1e-12);
    const Point2 expected = PointAlong(line, s.distance);
    EXPECT_NEAR(s.point.x, expected.x, 1e-12);
    EXPECT_NEAR(s.point.y, expected.y, 1e-12);
    const LocateResult r = t->ReferenceLocate(s.point);
    const bool defined = r.type == LocationType::kFace ||
                         r.type == LocationType::kEdge ||
                         r.type == LocationType::kVertex;
    ASSERT_EQ(s.has_value, defined);
    EXPECT_EQ(s.triangle_id >= 0, defined);
    if (!defined) continue;
    ++with_value;
    EXPECT_NEAR(s.value, r.value, 1e-9);
    if (r.type == LocationType::kFace) {
      EXPECT_EQ(s.triangle_id, r.triangle_id);
    }
  }
  EXPECT_GT(with_value, 30u);
  EXPECT_EQ(profile.samples.back().segment, 3u);

  options.samples = 1;
  const Profile one = Trace(*t, line, options);
  ASSERT_EQ(one.samples.size(), 1u);
  EXPECT_EQ(one.samples[0].distance, 0);
  EXPECT_FALSE(one.samples[0].has_value);  // (-0.1, 0.2) is outside
  options.samples = 0;
  EXPECT_TRUE(Trace(*t, line, options).samples.empty());
}

TEST(ProfileTest, LimitsAndBadInput) {
  const auto t = test::BuildTriangulation(test::PlaneDataset(2000, 21));
  ASSERT_NE(t, nullptr);
  const std::vector<Point2> long_line = {{0.01, 0.5}, {0.99, 0.5}};
  ProfileOptions options;
  options.max_faces = 10;
  Profile profile;
  Status s = TraceProfile(t->mesh(), t->mesh().DefaultStart(), long_line,
                          options, &profile);
  EXPECT_EQ(s.code(), Status::Code::kResourceExhausted);
  EXPECT_NE(s.message().find("10"), std::string::npos) << s.message();
  options.max_faces = 100000;
  EXPECT_TRUE(TraceProfile(t->mesh(), t->mesh().DefaultStart(), long_line,
                           options, &profile)
                  .ok());

  for (const std::vector<Point2>& bad :
       std::vector<std::vector<Point2>>{{},
                                        {{0.5, 0.5}},
                                        {{0.5, 0.5}, {kNaN, 0.5}},
                                        {{0.5, kInf}, {0.5, 0.5}}}) {
    s = TraceProfile(t->mesh(), t->mesh().DefaultStart(), bad, ProfileOptions(),
                     &profile);
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << bad.size();
  }
}

TEST(ProfileTest, ZeroLengthAndSeveralSegments) {
  const auto t = test::BuildTriangulation(test::PlaneDataset(300, 31));
  ASSERT_NE(t, nullptr);
  const Point2 a{0.3, 0.3}, b{0.7, 0.4}, c{0.5, 0.8};
  const Profile point = Trace(*t, {a, a});
  EXPECT_EQ(point.length, 0);
  ASSERT_EQ(point.breakpoints.size(), 2u);
  for (const ProfilePoint& p : point.breakpoints) {
    EXPECT_EQ(p.kind, Kind::kLineVertex);
    EXPECT_EQ(p.segment, 0u);
    EXPECT_NEAR(p.value, test::Plane(a), 1e-9);
    EXPECT_GE(p.triangle_id, 0);
  }
  EXPECT_TRUE(point.gaps.empty());

  const Profile bent = Trace(*t, {a, b, b, c});
  EXPECT_NEAR(bent.length, Distance(a, b) + Distance(b, c), 1e-12);
  const auto vertices = OfKind(bent, Kind::kLineVertex);
  ASSERT_EQ(vertices.size(), 4u);
  const uint32_t segments[4] = {0, 1, 2, 2};
  for (int i = 0; i < 4; ++i) EXPECT_EQ(vertices[i].segment, segments[i]);
  EXPECT_NEAR(vertices[1].distance, Distance(a, b), 1e-12);
  EXPECT_EQ(vertices[2].distance, vertices[1].distance);
  for (const ProfilePoint& p : bent.breakpoints) {
    const uint32_t expected = p.distance < vertices[1].distance ? 0
                              : p.kind == Kind::kLineVertex     ? p.segment
                                                                : 2;
    EXPECT_EQ(p.segment, expected);
    EXPECT_NEAR(p.value, test::Plane(p.point), 1e-9);
  }
  EXPECT_EQ(bent.crossings, bent.breakpoints.size() - 4);
  EXPECT_GT(bent.crossings, 0u);
}

}  // namespace
}  // namespace locator
