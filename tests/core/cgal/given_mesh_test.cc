// BuildGivenMesh: a mesh given as triangles served without the constraint
// hierarchy is the mesh Triangulation::Build serves (same in-domain
// triangles, vertices, digest and facts) and answers as CGAL's locate on
// it; bad meshes are refused with Triangulation::Build's messages.

#include "server/core/cgal/given_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "locator/engine.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/serving_mesh.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

// The Delaunay triangles of `n` random points, less those whose centroid
// lies in one of two discs (a hole and a bite out of the border), plus
// repeats of a few points; points no kept triangle uses stay in the
// dataset.
Dataset HoledMesh(size_t n, uint64_t seed) {
  Dataset d = GenerateUniform(n, seed);
  for (const Point2& p : d.points) d.values.push_back(p.x * 3 - p.y);
  std::unique_ptr<Triangulation> t = test::BuildTriangulation(d);
  const auto near = [](const Point2& c, double x, double y, double r) {
    return std::hypot(c.x - x, c.y - y) < r;
  };
  for (auto f = t->cgal().finite_faces_begin();
       f != t->cgal().finite_faces_end(); ++f) {
    const std::array<uint32_t, 3> ids = t->CornerIds(f);
    Point2 c{0, 0};
    for (const uint32_t id : ids) {
      c.x += d.points[id].x / 3;
      c.y += d.points[id].y / 3;
    }
    if (near(c, 0.5, 0.5, 0.15) || near(c, 1.0, 0.3, 0.2)) continue;
    d.constraints.triangles.push_back(ids);
  }
  for (int k = 0; k < 5; ++k) {
    d.points.push_back(d.points[k * 7]);
    d.values.push_back(d.values[k * 7]);
  }
  return d;
}

std::set<std::array<uint32_t, 3>> InDomainTriangles(const ServingMesh& mesh) {
  std::set<std::array<uint32_t, 3>> triangles;
  for (uint32_t f = 0; f < mesh.num_triangles(); ++f) {
    std::array<uint32_t, 3> ids = mesh.CornerIds(f);
    std::sort(ids.begin(), ids.end());
    triangles.insert(ids);
  }
  return triangles;
}

TEST(GivenMeshTest, IsTheMeshTriangulationServes) {
  for (const uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const Dataset d = HoledMesh(3000, seed);
    ASSERT_TRUE(IsGivenMesh(d));
    const StatusOr<BuiltMesh> built = BuildGivenMesh(d);
    ASSERT_TRUE(built.ok()) << built.status().ToString();
    const BuiltMesh& given = *built;
    std::unique_ptr<Triangulation> t = test::BuildTriangulation(d);
    ASSERT_NE(t, nullptr);
    const ServingMesh& a = *given.mesh;
    const ServingMesh& b = t->mesh();
    EXPECT_EQ(a.num_vertices(), b.num_vertices());
    EXPECT_EQ(a.num_triangles(), b.num_triangles());
    EXPECT_EQ(a.num_faces(), b.num_faces());
    EXPECT_EQ(InDomainTriangles(a), InDomainTriangles(b));
    EXPECT_EQ(a.digest(), b.digest());
    EXPECT_EQ(a.hull().size(), b.hull().size());
    EXPECT_EQ(given.facts.constraints, t->num_constraints());
    EXPECT_EQ(given.facts.holes, t->num_holes());
    EXPECT_EQ(given.facts.holes, 1u);
    EXPECT_EQ(given.facts.duplicates_merged, t->duplicates_merged());
    const DomainOutline outline = OutlineOf(*t, kOutlineSize);
    ASSERT_EQ(given.facts.outline.boundary.size(), outline.boundary.size());
    for (size_t k = 0; k < outline.boundary.size(); ++k) {
      for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(given.facts.outline.boundary[k][i].x,
                  outline.boundary[k][i].x);
        EXPECT_EQ(given.facts.outline.boundary[k][i].y,
                  outline.boundary[k][i].y);
      }
    }
    EXPECT_TRUE(given.facts.outline.breaklines.empty());
  }
}

TEST(GivenMeshTest, EngineAnswersAsCgalLocate) {
  const Dataset d = HoledMesh(2000, 4);
  std::unique_ptr<Triangulation> t = test::BuildTriangulation(d);
  ASSERT_NE(t, nullptr);
  StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(d, EngineOptions());
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<Engine> engine = *std::move(created);
  std::vector<Point2> queries =
      test::UniformQueries(t->bounding_box().Inflated(0.2), 20000, 8);
  for (size_t i = 0; i < 500; ++i) queries.push_back(d.points[i]);
  for (const Point2& q : queries) {
    LocateResult got;
    ASSERT_TRUE(engine->Locate(q, &got).ok());
    const LocateResult reference = t->ReferenceLocate(q);
    ASSERT_TRUE(t->Agrees(q, got, reference))
        << test::DescribeAnswer(q, got) << " vs "
        << test::DescribeAnswer(q, reference);
  }
}

// The unit square's four corners and centre, and triangles over them.
Dataset Fan(std::vector<std::array<uint32_t, 3>> triangles,
            std::vector<Point2> more = {}) {
  Dataset d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  d.points.insert(d.points.end(), more.begin(), more.end());
  d.constraints.triangles = std::move(triangles);
  return d;
}

std::string Refusal(const Dataset& d) {
  const Status s = BuildGivenMesh(d).status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  // Triangulation::Build refuses it too.
  EXPECT_FALSE(Triangulation::Build(d).ok());
  return s.message();
}

TEST(GivenMeshTest, RefusesBadMeshes) {
  // Two triangles on the same side of their edge (0 1).
  EXPECT_EQ(Refusal(Fan({{0, 1, 4}, {0, 1, 2}})),
            "mesh triangle 1 (0 1 2) is not a face of the triangulation of "
            "the mesh's edges: it overlaps another triangle or contains a "
            "point");
  EXPECT_EQ(Refusal(Fan({{0, 1, 4}, {1, 4, 0}})),
            "mesh triangle 1 (1 4 0) repeats an earlier triangle");
  EXPECT_EQ(Refusal(Fan({{0, 1, 4}, {0, 1, 2}, {0, 1, 3}})),
            "mesh edge (0 1) is shared by triangles 0, 1 and 2 (not a "
            "manifold)");
  // Two triangles whose edges cross, named as Triangulation::Build does.
  Dataset cross;
  cross.points = {{0, 0}, {2, 0}, {0, 2}, {1, -1}, {1, 1.5}, {3, 1}};
  cross.constraints.triangles = {{0, 1, 2}, {3, 5, 4}};
  EXPECT_EQ(Refusal(cross),
            "mesh edge (0 1) of triangle 0 and mesh edge (3 4) of triangle "
            "1 cross at (1, 0): the mesh's triangles overlap");
  // A point no triangle uses, inside one.
  Dataset inside;
  inside.points = {{0, 0}, {4, 0}, {0, 4}, {1, 1}};
  inside.constraints.triangles = {{0, 1, 2}};
  EXPECT_EQ(Refusal(inside),
            "point 3 (1, 1) lies inside the mesh but is no triangle's corner");
  // A triangle inside another: no edge crosses, the sides disagree.
  Dataset nested;
  nested.points = {{0, 0}, {4, 0}, {0, 4}, {1, 1}, {2, 1}, {1, 2}};
  nested.constraints.triangles = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_NE(Refusal(nested).find("not a face"), std::string::npos);
  // A corner of one triangle on the edge of another.
  EXPECT_TRUE(Refusal(Fan({{0, 1, 3}, {1, 2, 4}}, {})).find("not a face") !=
              std::string::npos);
}

}  // namespace
}  // namespace locator
