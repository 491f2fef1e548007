// The serving mesh is the CGAL triangulation it was derived from, in flat
// arrays: same faces, corners, neighbours, constraints, domain and hull;
// triangles in-domain first and in Hilbert order; walks on it give CGAL's
// answers from any start.

#include "server/core/mesh/serving_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "common/hilbert.h"
#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/mesh_walk.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

// Uniform points inside a ring with a square hole and a breakline.
Dataset HoledDataset() {
  Dataset d = GenerateUniform(3000, 11);
  d.constraints.rings.push_back(
      Polyline{{{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}, {}});
  d.constraints.rings.push_back(
      Polyline{{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}, {}});
  d.constraints.breaklines.push_back(Polyline{{{0.2, 0.2}, {0.8, 0.3}}, {}});
  return d;
}

class ServingMeshTest : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    t_ = test::BuildTriangulation(GetParam() ? HoledDataset()
                                             : GenerateUniform(3000, 5));
    ASSERT_NE(t_, nullptr);
  }
  const ServingMesh& mesh() const { return t_->mesh(); }

  std::unique_ptr<Triangulation> t_;
};

TEST_P(ServingMeshTest, HasCgalsFacesNeighboursConstraintsAndDomain) {
  const auto& dt = t_->cgal();
  ASSERT_EQ(mesh().num_faces(), t_->num_faces());
  ASSERT_EQ(mesh().num_triangles(), t_->num_triangles());
  ASSERT_EQ(mesh().num_vertices(), t_->num_vertices());
  EXPECT_EQ(mesh().digest(), t_->VertexDigest());
  EXPECT_EQ(GetParam(), mesh().num_triangles() < mesh().num_faces());
  std::vector<bool> seen(mesh().num_faces(), false);
  size_t constrained = 0;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const uint32_t m = t_->MeshFace(f);
    ASSERT_LT(m, mesh().num_faces());
    EXPECT_FALSE(seen[m]) << "face " << m << " twice";
    seen[m] = true;
    EXPECT_EQ(mesh().InDomain(m), t_->InDomain(f));
    // CGAL's corners, rotated so that the smallest id comes first.
    const std::array<uint32_t, 3> ids = mesh().CornerIds(m);
    EXPECT_LT(ids[0], std::min(ids[1], ids[2]));
    for (int i = 0; i < 3; ++i) {
      const int j = t_->MeshIndex(f, i);
      EXPECT_EQ(t_->MeshIndex(f, Ccw(i)), Ccw(j));  // a rotation
      EXPECT_EQ(ids[j], t_->CornerIds(f)[i]);
      const auto n = f->neighbor(i);
      const uint32_t raw = mesh().Neighbor(m, j);
      if (t_->IsInfinite(n)) {
        ASSERT_TRUE(ServingMesh::IsHull(raw));
        EXPECT_EQ(mesh().hull()[raw & ServingMesh::kIndexMask],
                  ServingMesh::Edge(m, j));
      } else {
        EXPECT_EQ(raw, t_->MeshFace(n));
        EXPECT_EQ(mesh().MirrorIndex(raw, m), t_->MeshIndex(n, n->index(f)));
      }
      EXPECT_EQ(mesh().IsConstrained(m, j), f->is_constrained(i));
      constrained += f->is_constrained(i);
    }
  }
  EXPECT_EQ(GetParam(), constrained > 0);
}

TEST_P(ServingMeshTest, HullIsOneClosedChain) {
  const auto hull = mesh().hull();
  ASSERT_GE(hull.size(), 3u);
  const auto ends = [&](uint32_t edge) {
    const uint32_t f = ServingMesh::EdgeFace(edge);
    const int i = ServingMesh::EdgeIndex(edge);
    return std::array<uint32_t, 2>{mesh().Corner(f, Ccw(i)),
                                   mesh().Corner(f, Cw(i))};
  };
  // Consecutive edges share an endpoint, all the same way round.
  const bool forward = ends(hull[0])[1] == ends(hull[1])[0];
  for (size_t k = 0; k < hull.size(); ++k) {
    const auto a = ends(hull[k]);
    const auto b = ends(hull[(k + 1) % hull.size()]);
    EXPECT_EQ(forward ? a[1] : a[0], forward ? b[0] : b[1]) << "edge " << k;
  }
}

TEST_P(ServingMeshTest, TrianglesAreInDomainFirstThenAlongTheHilbertCurve) {
  const auto key = [&](uint32_t f) {
    Point2 c{0, 0};
    for (int i = 0; i < 3; ++i) {
      c.x += mesh().CornerPoint(f, i).x / 3;
      c.y += mesh().CornerPoint(f, i).y / 3;
    }
    return HilbertKey(c, mesh().bounding_box());
  };
  for (uint32_t f = 1; f < mesh().num_faces(); ++f) {
    if (f == mesh().num_triangles()) continue;  // the second group starts
    EXPECT_LE(key(f - 1), key(f)) << "face " << f;
  }
}

TEST_P(ServingMeshTest, FacesWithCornersFindsEveryFaceFromAnyCorner) {
  std::vector<std::array<uint32_t, 3>> ids;
  for (uint32_t f = 0; f < mesh().num_faces(); ++f) {
    const auto c = mesh().CornerIds(f);
    ids.push_back({c[f % 3], c[(f + 1) % 3], c[(f + 2) % 3]});
  }
  const std::vector<uint32_t> found = mesh().FacesWithCorners(ids);
  for (uint32_t f = 0; f < mesh().num_faces(); ++f) {
    EXPECT_EQ(found[f], f);
  }
  // Clockwise, or a vertex that does not exist: no face.
  const auto c = mesh().CornerIds(0);
  const std::vector<std::array<uint32_t, 3>> bad = {{c[0], c[2], c[1]},
                                                    {c[0], c[1], 1u << 30}};
  EXPECT_EQ(
      mesh().FacesWithCorners(bad),
      (std::vector<uint32_t>{ServingMesh::kNoFace, ServingMesh::kNoFace}));
}

TEST_P(ServingMeshTest, WalksFromAnyStartGiveCgalsAnswers) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> coordinate(-0.2, 1.2);
  std::vector<Point2> queries;
  for (int k = 0; k < 3000; ++k) {
    queries.push_back({coordinate(random), coordinate(random)});
  }
  // Vertices and points on edges, exactly.
  for (uint32_t f = 0; f < mesh().num_faces(); f += 7) {
    queries.push_back(mesh().CornerPoint(f, 0));
    const Point2& a = mesh().CornerPoint(f, 1);
    const Point2& b = mesh().CornerPoint(f, 2);
    if (a.x == b.x || a.y == b.y) queries.push_back({a.x, (a.y + b.y) / 2});
  }
  for (const Point2& q : queries) {
    const auto start = static_cast<uint32_t>(random() % mesh().num_faces());
    LocateResult got;
    WalkAndDescribe(mesh(), start, q, &got);
    const LocateResult reference = t_->ReferenceLocate(q);
    EXPECT_TRUE(t_->Agrees(q, got, reference))
        << "(" << q.x << ", " << q.y << ") from face " << start;
    EXPECT_EQ(got.triangle_id >= 0, reference.triangle_id >= 0);
  }
}

TEST_P(ServingMeshTest, ClearWalksDecideOnlyWhatCgalSays) {
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> coordinate(-0.2, 1.2);
  int decided = 0;
  for (int k = 0; k < 3000; ++k) {
    const Point2 q{coordinate(random), coordinate(random)};
    const auto start = static_cast<uint32_t>(random() % mesh().num_faces());
    Triangulation::Cdt::Locate_type type;
    int index = 0;
    const auto cgal_face =
        t_->cgal().locate(Triangulation::Cdt::Point(q.x, q.y), type, index);
    MeshWalkOutcome walk{.face = start};
    if (!ClearWalk(mesh(), q, /*max_steps=*/1000, &walk)) {
      ASSERT_LT(walk.face, mesh().num_faces());
      continue;
    }
    ++decided;
    if (walk.type == LocationType::kFace) {
      ASSERT_EQ(type, Triangulation::Cdt::FACE) << q.x << ", " << q.y;
      EXPECT_EQ(t_->MeshFace(cgal_face), walk.face) << q.x << ", " << q.y;
    } else {
      ASSERT_EQ(walk.type, LocationType::kOutsideConvexHull);
      ASSERT_EQ(type, Triangulation::Cdt::OUTSIDE_CONVEX_HULL)
          << q.x << ", " << q.y;
      // The hull edge it names has q strictly beyond it.
      EXPECT_TRUE(
          ServingMesh::IsHull(mesh().Neighbor(walk.face, walk.feature)));
      EXPECT_EQ(Orientation(mesh().CornerPoint(walk.face, Ccw(walk.feature)),
                            mesh().CornerPoint(walk.face, Cw(walk.feature)), q),
                Side::kRight);
    }
  }
  // Random points from any start are almost all decided by the filter.
  EXPECT_GT(decided, 3000 * 9 / 10);
  // Vertices and points on edges are never decided.
  for (uint32_t f = 0; f < mesh().num_faces(); f += 7) {
    const Point2& a = mesh().CornerPoint(f, 1);
    const Point2& b = mesh().CornerPoint(f, 2);
    MeshWalkOutcome walk{.face = f};
    EXPECT_FALSE(ClearWalk(mesh(), a, /*max_steps=*/1000, &walk));
    if (a.x == b.x || a.y == b.y) {
      walk = MeshWalkOutcome{.face = f};
      EXPECT_FALSE(ClearWalk(mesh(), Point2{a.x, (a.y + b.y) / 2},
                             /*max_steps=*/1000, &walk));
    }
  }
  // No step allowed: only q in the start face itself, one face tested.
  const uint32_t f = 0;
  const Point2 centroid{
      (mesh().CornerPoint(f, 0).x + mesh().CornerPoint(f, 1).x +
       mesh().CornerPoint(f, 2).x) /
          3,
      (mesh().CornerPoint(f, 0).y + mesh().CornerPoint(f, 1).y +
       mesh().CornerPoint(f, 2).y) /
          3};
  MeshWalkOutcome walk{.face = f};
  EXPECT_TRUE(ClearWalk(mesh(), centroid, /*max_steps=*/0, &walk));
  EXPECT_EQ(walk.face, f);
  EXPECT_EQ(walk.faces_visited, 1u);
}

INSTANTIATE_TEST_SUITE_P(PlainAndHoled, ServingMeshTest,
                         ::testing::Values(false, true));

}  // namespace
}  // namespace locator
