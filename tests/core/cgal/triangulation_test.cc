#include "server/core/cgal/triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using test::BuildTriangulation;
using test::PointsDataset;

// The InvalidArgument message Build() fails with for `dataset`.
std::string BuildError(const Dataset& dataset) {
  const Status s = Triangulation::Build(dataset).status();
  EXPECT_FALSE(s.ok()) << "built from " << dataset.points.size() << " points";
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  return s.message();
}

// Number of vertices on the convex hull.
size_t HullVertices(const Triangulation& t) {
  return t.cgal().degree(t.cgal().infinite_vertex());
}

// Euler's relation for a triangulation of n points with h on the hull.
size_t EulerTriangles(const Triangulation& t) {
  return 2 * t.num_vertices() - 2 - HullVertices(t);
}

TEST(TriangulationBuildTest, FewerThanThreePointsFail) {
  for (size_t n = 0; n < 3; ++n) {
    std::vector<Point2> points;
    for (size_t i = 0; i < n; ++i) points.push_back({double(i), double(i * i)});
    const std::string msg = BuildError(PointsDataset(points));
    EXPECT_NE(msg.find(std::to_string(n) + " distinct"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("at least 3"), std::string::npos) << msg;
  }
}

TEST(TriangulationBuildTest, ThreePointsWithADuplicateFail) {
  const std::string msg = BuildError(PointsDataset({{0, 0}, {1, 0}, {0, 0}}));
  EXPECT_NE(msg.find("2 distinct"), std::string::npos) << msg;
}

TEST(TriangulationBuildTest, CollinearPointsFail) {
  std::vector<Point2> diagonal, vertical;
  for (int i = 0; i < 10; ++i) {
    diagonal.push_back({double(i), 2.0 * i + 1});
    vertical.push_back({3, double(9 - i)});
  }
  diagonal.push_back(diagonal[4]);  // duplicates do not rescue it
  for (const auto& points : {diagonal, vertical}) {
    const std::string msg = BuildError(PointsDataset(points));
    EXPECT_NE(msg.find("collinear"), std::string::npos) << msg;
    EXPECT_NE(msg.find("10 distinct"), std::string::npos) << msg;
  }
}

TEST(TriangulationBuildTest, NonFinitePointFailsNamingIt) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::string msg =
      BuildError(PointsDataset({{0, 0}, {1, 0}, {0, 1}, {inf, 2}}));
  EXPECT_NE(msg.find("point 3"), std::string::npos) << msg;
}

TEST(TriangulationBuildTest, ValuesOfTheWrongSizeFail) {
  Dataset ds = PointsDataset({{0, 0}, {1, 0}, {0, 1}});
  ds.values = {1, 2};
  BuildError(ds);
}

TEST(TriangulationBuildTest, ExactlyThreePointsMakeOneTriangle) {
  auto t = BuildTriangulation(PointsDataset({{0, 0}, {4, 0}, {0, 4}}));
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->num_vertices(), 3u);
  EXPECT_EQ(t->num_triangles(), 1u);
  EXPECT_EQ(t->duplicates_merged(), 0u);
  const LocateResult r = t->ReferenceLocate({1, 1});
  EXPECT_EQ(r.type, LocationType::kFace);
  EXPECT_EQ(r.triangle_id, 0);
  std::array<int64_t, 3> ids = r.vertex_ids;
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::array<int64_t, 3>{0, 1, 2}));
}

TEST(TriangulationBuildTest, DuplicatesMergeIntoTheFirstOccurrence) {
  const Point2 a{0, 0}, b{1, 0}, c{0, 1}, d{1, 1};
  Dataset ds = PointsDataset({b, a, c, a, b, d, a});
  ds.values = {10, 20, 30, 40, 50, 60, 70};
  auto t = BuildTriangulation(ds);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->input_points(), 7u);
  EXPECT_EQ(t->num_vertices(), 4u);
  EXPECT_EQ(t->duplicates_merged(), 3u);
  Point2 p;
  for (int64_t merged : {3, 4, 6}) EXPECT_FALSE(t->VertexPoint(merged, &p));
  EXPECT_FALSE(t->VertexPoint(7, &p));
  EXPECT_FALSE(t->VertexPoint(-1, &p));
  ASSERT_TRUE(t->VertexPoint(1, &p));
  EXPECT_TRUE(p.x == a.x && p.y == a.y);
  // Every copy maps to the surviving vertex, which keeps the first id.
  EXPECT_EQ(t->VertexOfInput(3)->info().id, 1);
  EXPECT_EQ(t->VertexOfInput(6)->info().id, 1);
  EXPECT_EQ(t->VertexOfInput(4)->info().id, 0);
  // The first occurrence's value wins.
  const LocateResult r = t->ReferenceLocate(a);
  ASSERT_EQ(r.type, LocationType::kVertex);
  EXPECT_EQ(r.vertex_ids[r.feature_index], 1);
  EXPECT_EQ(r.value, 20);
  EXPECT_EQ(t->ReferenceLocate(b).value, 10);
}

TEST(TriangulationTest, TriangleIdsAreZeroToFMinusOneAndUnique) {
  auto t = BuildTriangulation(GenerateUniform(2000, 3));
  ASSERT_NE(t, nullptr);
  std::vector<int64_t> ids;
  const auto& dt = t->cgal();
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
    if (t->IsInfinite(f)) {
      EXPECT_EQ(f->info(), -1);
    } else {
      ids.push_back(f->info());
    }
  }
  ASSERT_EQ(ids.size(), t->num_triangles());
  std::sort(ids.begin(), ids.end());
  std::vector<int64_t> expected(ids.size());
  std::iota(expected.begin(), expected.end(), 0);
  EXPECT_EQ(ids, expected);
}

TEST(TriangulationTest, IntegerGridHasEulerCounts) {
  constexpr int k = 50;
  auto t = BuildTriangulation(test::GridDataset(k));
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->num_vertices(), size_t{k * k});
  EXPECT_EQ(t->duplicates_merged(), 0u);
  EXPECT_EQ(HullVertices(*t), size_t{4 * (k - 1)});
  EXPECT_EQ(t->num_triangles(), size_t{2 * (k - 1) * (k - 1)});
  const BoundingBox& box = t->bounding_box();
  EXPECT_EQ(box.min_x, 0);
  EXPECT_EQ(box.min_y, 0);
  EXPECT_EQ(box.max_x, k - 1);
  EXPECT_EQ(box.max_y, k - 1);
}

TEST(TriangulationTest, DenseClusterInsideSparseData) {
  const Dataset ds = test::DenseClusterDataset(2000, 2000, 1e-6, 5);
  auto t = BuildTriangulation(ds);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->num_vertices(), 4000u);
  EXPECT_EQ(t->num_triangles(), EulerTriangles(*t));
  // Every input point is found as itself, in the cluster as elsewhere.
  for (size_t i = 0; i < ds.points.size(); ++i) {
    const LocateResult r = t->ReferenceLocate(ds.points[i]);
    ASSERT_EQ(r.type, LocationType::kVertex) << "point " << i;
    EXPECT_EQ(r.vertex_ids[r.feature_index], int64_t(i));
  }
  // Random points in the cluster are well-formed answers.
  const test::TriangleIndex index(*t);
  const BoundingBox cluster{0.5, 0.5, 0.5 + 1e-6, 0.5 + 1e-6};
  for (const Point2& q : test::UniformQueries(cluster, 2000, 9)) {
    const LocateResult r = t->ReferenceLocate(q);
    ASSERT_TRUE(test::AnswerIsConsistent(*t, index, q, r));
    EXPECT_EQ(r.type, LocationType::kFace);
  }
}

TEST(TriangulationTest, ValuesInterpolateLinearly) {
  const Dataset ds = test::PlaneDataset(2000, 11);
  auto t = BuildTriangulation(ds);
  ASSERT_NE(t, nullptr);
  ASSERT_TRUE(t->has_values());
  const BoundingBox interior{0.05, 0.05, 0.95, 0.95};
  for (const Point2& q : test::UniformQueries(interior, 5000, 12)) {
    const LocateResult r = t->ReferenceLocate(q);
    ASSERT_TRUE(r.has_value);
    EXPECT_NEAR(r.value, test::Plane(q), 1e-9) << q.x << ", " << q.y;
  }
  for (size_t i = 0; i < 100; ++i) {
    const LocateResult r = t->ReferenceLocate(ds.points[i]);
    EXPECT_EQ(r.value, ds.values[i]);
  }
  // Outside the hull there is nothing to interpolate.
  EXPECT_FALSE(t->ReferenceLocate({2, 2}).has_value);
}

TEST(TriangulationTest, SampleEdgesTakesAllOrAnEvenShareOfRealEdges) {
  constexpr int k = 50;
  auto t = BuildTriangulation(test::GridDataset(k));
  ASSERT_NE(t, nullptr);
  const ServingMesh& mesh = t->mesh();
  const size_t edges = t->num_vertices() + t->num_triangles() - 1;
  EXPECT_EQ(mesh.SampleEdges(edges).size(), edges);
  EXPECT_EQ(mesh.SampleEdges(10 * edges).size(), edges);
  EXPECT_TRUE(mesh.SampleEdges(0).empty());
  const auto sample = mesh.SampleEdges(1000);
  EXPECT_LE(sample.size(), 1000u);
  EXPECT_GE(sample.size(), 500u);
  // Grid edges: unit axis-parallel segments or unit-square diagonals.
  for (const auto& [a, b] : sample) {
    const double dx = std::abs(a.x - b.x);
    const double dy = std::abs(a.y - b.y);
    EXPECT_TRUE((dx == 1 || dx == 0) && (dy == 1 || dy == 0) && dx + dy > 0)
        << a.x << "," << a.y << " - " << b.x << "," << b.y;
  }
}

TEST(TriangulationTest, MemoryBytesGrowsWithN) {
  auto small = BuildTriangulation(GenerateUniform(1000, 1));
  auto large = BuildTriangulation(GenerateUniform(20000, 1));
  ASSERT_NE(small, nullptr);
  ASSERT_NE(large, nullptr);
  EXPECT_GT(small->MemoryBytes(), 1000u * 2 * sizeof(void*));
  EXPECT_GT(large->MemoryBytes(), 10 * small->MemoryBytes());
}

// Any finite input is accepted, so barycentrics (and the interpolated
// value) must stay finite at every coordinate scale. The triangle
// (0,0) (2s,0) (0,2s) with values 1, 2, 3 and q = (s/2, s/2) has barycentrics
// (0.5, 0.25, 0.25) and value 1.75; the midpoint (s, 0) of the bottom edge
// has (0.5, 0.5, 0) and value 1.5.
class ExtremeScaleTest : public ::testing::TestWithParam<double> {};

TEST_P(ExtremeScaleTest, BarycentricsAndValuesStayFinite) {
  const double s = GetParam();
  Dataset ds = PointsDataset({{0, 0}, {2 * s, 0}, {0, 2 * s}});
  ds.values = {1, 2, 3};
  auto t = BuildTriangulation(ds);
  ASSERT_NE(t, nullptr);
  struct Case {
    Point2 q;
    LocationType type;
    double value;
  };
  for (const Case& c : {Case{{s / 2, s / 2}, LocationType::kFace, 1.75},
                        Case{{s, 0}, LocationType::kEdge, 1.5}}) {
    const LocateResult r = t->ReferenceLocate(c.q);
    ASSERT_EQ(r.type, c.type);
    const double sum = r.barycentric[0] + r.barycentric[1] + r.barycentric[2];
    EXPECT_NEAR(sum, 1, 1e-12) << "barycentrics " << r.barycentric[0] << " "
                               << r.barycentric[1] << " " << r.barycentric[2];
    EXPECT_NEAR(r.value, c.value, 1e-12) << LocationTypeName(c.type);
  }
}

std::string ScaleName(const ::testing::TestParamInfo<double>& info) {
  const double s = info.param;
  const int exponent = static_cast<int>(std::lround(std::log10(s)));
  if (exponent == 0) return "Unit";
  return (exponent > 0 ? "Huge1e" : "Tiny1em") +
         std::to_string(std::abs(exponent));
}

INSTANTIATE_TEST_SUITE_P(Scales, ExtremeScaleTest,
                         ::testing::Values(1.0, 1e150, 1e-150, 1e300, 1e-200),
                         ScaleName);

// A needle spanning 450 orders of magnitude: in long double its area
// cancels to 0 (or worse), so the barycentrics come from exact rationals.
// Expected values computed with Python's fractions.Fraction.
TEST(TriangulationTest, NeedleTriangleBarycentricsAreExact) {
  auto t = BuildTriangulation(
      PointsDataset({{1e150, -3e150}, {7e-150, 5e-151}, {4e-300, 0}}));
  ASSERT_NE(t, nullptr);
  const LocateResult r = t->ReferenceLocate({9e-200, -3e-200});
  ASSERT_EQ(r.type, LocationType::kFace);
  std::array<double, 3> by_input_id{};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(std::isfinite(r.barycentric[i])) << i;
    by_input_id[r.vertex_ids[i]] = r.barycentric[i];
  }
  EXPECT_GE(by_input_id[0], 0);
  EXPECT_LT(by_input_id[0], 1e-300);
  EXPECT_NEAR(by_input_id[1], 1.116279069767442e-50, 1e-62);
  EXPECT_DOUBLE_EQ(by_input_id[2], 1.0);
}

// The square (0,0) (2,0) (2,2) (0,2) with its centre (1,1): four triangles
// around vertex 4.
class SquareTest : public ::testing::Test {
 protected:
  void SetUp() override {
    t_ = BuildTriangulation(
        PointsDataset({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}}));
    ASSERT_NE(t_, nullptr);
    ASSERT_EQ(t_->num_triangles(), 4u);
  }

  // The endpoints of the edge an kEdge answer lies on, sorted.
  static std::set<int64_t> EdgeOf(const LocateResult& r) {
    return {r.vertex_ids[(r.feature_index + 1) % 3],
            r.vertex_ids[(r.feature_index + 2) % 3]};
  }

  std::unique_ptr<Triangulation> t_;
};

TEST_F(SquareTest, ReferenceLocateTypes) {
  const LocateResult vertex = t_->ReferenceLocate({1, 1});
  ASSERT_EQ(vertex.type, LocationType::kVertex);
  EXPECT_EQ(vertex.vertex_ids[vertex.feature_index], 4);
  EXPECT_EQ(vertex.barycentric[vertex.feature_index], 1);

  const LocateResult inner_edge = t_->ReferenceLocate({0.5, 0.5});
  ASSERT_EQ(inner_edge.type, LocationType::kEdge);
  EXPECT_EQ(EdgeOf(inner_edge), (std::set<int64_t>{0, 4}));
  EXPECT_EQ(inner_edge.barycentric[inner_edge.feature_index], 0);

  const LocateResult hull_edge = t_->ReferenceLocate({1, 0});
  ASSERT_EQ(hull_edge.type, LocationType::kEdge);
  EXPECT_EQ(EdgeOf(hull_edge), (std::set<int64_t>{0, 1}));
  EXPECT_GE(hull_edge.triangle_id, 0);  // the finite side of the edge

  const LocateResult face = t_->ReferenceLocate({1, 0.5});
  ASSERT_EQ(face.type, LocationType::kFace);
  for (int i = 0; i < 3; ++i) {
    const double expected = face.vertex_ids[i] == 4 ? 0.5 : 0.25;
    EXPECT_NEAR(face.barycentric[i], expected, 1e-15);
  }

  const LocateResult outside = t_->ReferenceLocate({3, 1});
  ASSERT_EQ(outside.type, LocationType::kOutsideConvexHull);
  // Oriented counter-clockwise along the hull: q is on its right.
  EXPECT_EQ(outside.hull_edge_ids, (std::array<int64_t, 2>{1, 2}));
  EXPECT_FALSE(outside.has_value);
  const LocateResult below = t_->ReferenceLocate({1, -5});
  ASSERT_EQ(below.type, LocationType::kOutsideConvexHull);
  EXPECT_EQ(below.hull_edge_ids, (std::array<int64_t, 2>{0, 1}));
}

TEST_F(SquareTest, AgreesAcceptsEquivalentAnswers) {
  const Point2 edge_point{0.5, 0.5};
  const LocateResult ref = t_->ReferenceLocate(edge_point);
  // The other triangle on edge 0-4, as an answer of the same type.
  LocateResult other = t_->ReferenceLocate({0.4, 0.6});
  ASSERT_NE(other.triangle_id, ref.triangle_id);
  other.type = LocationType::kEdge;
  EXPECT_TRUE(t_->Agrees(edge_point, other, ref));

  const Point2 centre{1, 1};
  LocateResult any_around = t_->ReferenceLocate({1.5, 1.2});
  any_around.type = LocationType::kVertex;
  EXPECT_TRUE(t_->Agrees(centre, any_around, t_->ReferenceLocate(centre)));
}

TEST_F(SquareTest, AgreesRejectsWrongAnswers) {
  const Point2 q{1, 0.5};
  const LocateResult ref = t_->ReferenceLocate(q);
  EXPECT_TRUE(t_->Agrees(q, ref, ref));
  // A different face.
  EXPECT_FALSE(t_->Agrees(q, t_->ReferenceLocate({1, 1.5}), ref));
  // The right face with the wrong type.
  LocateResult wrong_type = ref;
  wrong_type.type = LocationType::kEdge;
  EXPECT_FALSE(t_->Agrees(q, wrong_type, ref));
  // A face answer for a point on an edge.
  const Point2 on_edge{0.5, 0.5};
  LocateResult face_for_edge = t_->ReferenceLocate(on_edge);
  face_for_edge.type = LocationType::kFace;
  EXPECT_FALSE(
      t_->Agrees(on_edge, face_for_edge, t_->ReferenceLocate(on_edge)));
  // A triangle that lacks the vertex.
  LocateResult far_face = t_->ReferenceLocate({1, 0.2});
  far_face.vertex_ids = {0, 1, 3};
  far_face.type = LocationType::kVertex;
  EXPECT_FALSE(t_->Agrees({2, 2}, far_face, t_->ReferenceLocate({2, 2})));
}

TEST_F(SquareTest, AgreesRejectsHullEdgesThatDoNotSeeQ) {
  const Point2 q{3, 1};
  const LocateResult ref = t_->ReferenceLocate(q);
  ASSERT_TRUE(t_->Agrees(q, ref, ref));
  const std::array<int64_t, 2> bad_edges[] = {
      {3, 0},   // the opposite hull edge: q is on its inner side
      {2, 1},   // the right edge, reversed
      {0, 1},   // the bottom hull edge: q is on its inner side
      {0, 4},   // an inner edge
      {0, 2},   // not an edge at all
      {1, 7},   // no such vertex
      {-1, 2},  // no such vertex
  };
  for (const auto& edge : bad_edges) {
    LocateResult got = ref;
    got.hull_edge_ids = edge;
    EXPECT_FALSE(t_->Agrees(q, got, ref)) << edge[0] << "-" << edge[1];
  }
  // The other hull edge that sees a corner point is fine.
  const Point2 corner{3, 3};
  LocateResult top = ref;
  top.hull_edge_ids = {2, 3};
  EXPECT_TRUE(t_->Agrees(corner, top, t_->ReferenceLocate(corner)));
  top.hull_edge_ids = {1, 2};
  EXPECT_TRUE(t_->Agrees(corner, top, t_->ReferenceLocate(corner)));
}

}  // namespace
}  // namespace locator
