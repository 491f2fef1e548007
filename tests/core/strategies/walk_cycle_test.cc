// The visibility walk cycles on a non-Delaunay mesh; locator's strategies
// must not.
//
// Devillers, Pion and Teillaud ("Walking in a triangulation", SoCG 2001;
// IJFCS 13(2), 2002) show that the deterministic visibility walk (leave each
// triangle by the first of its edges, in a fixed order, that has the query
// strictly on its far side) can loop forever in a triangulation that is not
// Delaunay, which is why a walk must randomise its edge order (or remember
// more). Their example is a ring of triangles around the query's
// triangle. The windmill below is ours, not their published coordinates,
// with the same property: an inner triangle A0 A1 A2 around the query
// q = (0, 0), an outer triangle B0 B1 B2 turned about 10 degrees further, and
// the ring between them cut into six thin triangles whose spokes A_i B_i and
// A_i B_(i+1) all pass q on the same side. From any ring triangle, q is
// beyond the spoke ahead of it; with the edges tried in the order of their
// opposite corner's id (the A's have smaller ids than the B's), that spoke
// comes before the inner edge, so the walk goes round the ring for ever and
// never enters the inner triangle.
//
// The tests check that the example is real (the deterministic walk written
// here revisits a face before reaching q, on the mesh the oracle builds,
// while the same walk on the Delaunay triangulation of the same points
// reaches q), then that every strategy, through Engine, terminates and
// agrees with CGAL's locate() on the windmill and on a mesh of 64 of them
// (the gaps filled by a constrained triangulation, all served as given).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "locator/engine.h"
#include "server/core/cgal/triangulation.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using Face_handle = Triangulation::Face_handle;

// One windmill around the origin: A0 A1 A2 then B0 B1 B2 (ids 0..5 when
// alone), integers so that every vertex and edge midpoint is exact.
constexpr std::array<Point2, 6> kWindmill = {
    {{0, 10}, {-9, -5}, {9, -5}, {-5, 30}, {-23, -19}, {28, -10}}};
// Corner indices into kWindmill, counter-clockwise: the inner triangle,
// then the ring (A_i B_i B_(i+1) and A_i B_(i+1) A_(i+1), i = 0..2).
constexpr std::array<std::array<uint32_t, 3>, 7> kWindmillTriangles = {{
    {0, 1, 2},
    {0, 3, 4},
    {0, 4, 1},
    {1, 4, 5},
    {1, 5, 2},
    {2, 5, 3},
    {2, 3, 0},
}};
// Windmills are laid out on a grid with this pitch (the outer triangle
// spans 51 x 49).
constexpr double kPitch = 70;
// A walk that has not arrived after this many steps counts as looping.
constexpr int kMaxSteps = 1000;

const char* const kStrategies[] = {"walk", "jump-and-walk", "adaptive-paper",
                                   "self-tuning"};

// side x side windmills, windmill (i, j) centred on (i, j) * kPitch with
// points 6 (j * side + i) + 0..5, as a mesh served as given. With more than
// one, the gaps between them are filled by the constrained Delaunay
// triangulation of all the points with every windmill edge as a breakline.
// Sets `centres` to the query inside each windmill's inner triangle.
Dataset WindmillMesh(int side, std::vector<Point2>* centres) {
  Dataset mesh;
  mesh.source = "windmills";
  Dataset fill;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const Point2 centre{i * kPitch, j * kPitch};
      centres->push_back(centre);
      const uint32_t first = static_cast<uint32_t>(mesh.points.size());
      for (const Point2& p : kWindmill) {
        mesh.points.push_back({centre.x + p.x, centre.y + p.y});
      }
      for (const auto& [a, b, c] : kWindmillTriangles) {
        mesh.constraints.triangles.push_back({first + a, first + b, first + c});
        for (const auto& [u, v] : {std::pair{a, b}, {b, c}, {c, a}}) {
          fill.constraints.breaklines.push_back(
              Polyline{{mesh.points[first + u], mesh.points[first + v]}, {}});
        }
      }
    }
  }
  if (side == 1) return mesh;
  fill.points = mesh.points;
  const std::unique_ptr<Triangulation> filled = test::BuildTriangulation(fill);
  if (filled == nullptr) return mesh;
  mesh.constraints.triangles.clear();
  const auto& dt = filled->cgal();
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    mesh.constraints.triangles.push_back(filled->CornerIds(f));
  }
  return mesh;
}

struct DeterministicWalk {
  size_t steps = 0;
  bool arrived = false;    // in a face whose closed triangle holds q
  bool revisited = false;  // came back to a face it had left
};

// The deterministic visibility walk from `start` to q: in each face, try
// the edges in the order of their opposite corner's id, smallest first, and
// cross the first one that has q strictly on its far side (CGAL's exact
// orientation). Stops on arrival, on entering a face for the second time,
// or after kMaxSteps.
DeterministicWalk WalkWithFixedEdgeOrder(const Triangulation& t,
                                         Face_handle start, const Point2& q) {
  const auto& dt = t.cgal();
  const Triangulation::CgalPoint target = Triangulation::ToCgal(q);
  DeterministicWalk walk;
  std::set<Face_handle> seen = {start};
  Face_handle f = start;
  while (walk.steps < kMaxSteps) {
    const std::array<uint32_t, 3> ids = t.CornerIds(f);
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&ids](int a, int b) { return ids[a] < ids[b]; });
    int exit = -1;
    for (const int i : order) {
      if (CGAL::orientation(f->vertex(dt.ccw(i))->point(),
                            f->vertex(dt.cw(i))->point(),
                            target) == CGAL::RIGHT_TURN) {
        exit = i;
        break;
      }
    }
    if (exit < 0) {
      walk.arrived = true;
      return walk;
    }
    f = f->neighbor(exit);
    ++walk.steps;
    if (dt.is_infinite(f)) return walk;  // q is outside the hull
    if (!seen.insert(f).second) {
      walk.revisited = true;
      return walk;
    }
  }
  return walk;
}

// The face with corners `ids` (counter-clockwise), which must exist.
Face_handle FaceOf(const Triangulation& t, std::array<uint32_t, 3> ids) {
  Face_handle f;
  EXPECT_TRUE(t.FaceWithCorners(ids, &f))
      << ids[0] << " " << ids[1] << " " << ids[2];
  return f;
}

// A windmill mesh, the query in each windmill, and the oracle's
// triangulation of the mesh (nullptr, and a test failure, if it fails).
struct Windmills {
  Dataset mesh;
  std::vector<Point2> centres;
  std::unique_ptr<Triangulation> t;
};

Windmills MakeWindmills(int side) {
  Windmills w;
  w.mesh = WindmillMesh(side, &w.centres);
  w.t = test::BuildTriangulation(w.mesh);
  return w;
}

TEST(WalkCycleTest, DeterministicWalkLoopsRoundTheWindmill) {
  const Windmills w = MakeWindmills(1);
  ASSERT_NE(w.t, nullptr);
  const Triangulation* t = w.t.get();
  ASSERT_EQ(t->num_triangles(), kWindmillTriangles.size());
  // Not Delaunay: CGAL's Delaunay triangulation of the same six points
  // differs (the ring triangles are too thin).
  Dataset points = w.mesh;
  points.constraints = {};
  const auto delaunay = test::BuildTriangulation(points);
  ASSERT_NE(delaunay, nullptr);

  const Point2 q = w.centres[0];
  ASSERT_EQ(t->ReferenceLocate(q).type, LocationType::kFace);
  for (size_t k = 1; k < kWindmillTriangles.size(); ++k) {
    SCOPED_TRACE("from ring triangle " + std::to_string(k));
    const DeterministicWalk walk =
        WalkWithFixedEdgeOrder(*t, FaceOf(*t, kWindmillTriangles[k]), q);
    EXPECT_TRUE(walk.revisited);
    EXPECT_FALSE(walk.arrived);
    EXPECT_EQ(walk.steps, 6u);  // once round the ring of six
  }
  // The same walk in the inner triangle has arrived, and on the Delaunay
  // triangulation it arrives from every face: the loop is the mesh's.
  EXPECT_TRUE(
      WalkWithFixedEdgeOrder(*t, FaceOf(*t, kWindmillTriangles[0]), q).arrived);
  bool delaunay_differs = false;
  const auto& dt = delaunay->cgal();
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const DeterministicWalk walk = WalkWithFixedEdgeOrder(*delaunay, f, q);
    EXPECT_TRUE(walk.arrived) << "from a Delaunay face";
    Face_handle same;
    delaunay_differs |= !t->FaceWithCorners(delaunay->CornerIds(f), &same);
  }
  EXPECT_TRUE(delaunay_differs);
}

TEST(WalkCycleTest, EveryWindmillOfTheTiledMeshTrapsTheWalk) {
  const Windmills w = MakeWindmills(8);
  ASSERT_NE(w.t, nullptr);
  for (size_t m = 0; m < w.centres.size(); ++m) {
    const uint32_t first = static_cast<uint32_t>(6 * m);
    for (size_t k = 1; k < kWindmillTriangles.size(); ++k) {
      std::array<uint32_t, 3> ids = kWindmillTriangles[k];
      for (uint32_t& id : ids) id += first;
      const DeterministicWalk walk =
          WalkWithFixedEdgeOrder(*w.t, FaceOf(*w.t, ids), w.centres[m]);
      EXPECT_TRUE(walk.revisited) << "windmill " << m << " triangle " << k;
    }
  }
}

// Every query of `queries`, through Engine::Locate and Engine::LocateBatch
// with every strategy, agrees with CGAL's locate() on `t`, built from the
// same dataset.
void ExpectEveryStrategyAgrees(const Dataset& dataset, const Triangulation& t,
                               const std::vector<Point2>& queries) {
  std::vector<LocateResult> want;
  for (const Point2& q : queries) want.push_back(t.ReferenceLocate(q));
  for (const char* strategy : kStrategies) {
    SCOPED_TRACE(strategy);
    EngineOptions options;
    options.strategy = strategy;
    options.tuning.warmup_queries = 200;
    options.tuning.retune_every = 200;
    const StatusOr<std::unique_ptr<Engine>> created =
        Engine::Create(dataset, options);
    ASSERT_TRUE(created.ok()) << created.status().ToString();
    const Engine* engine = created->get();
    // Twice over: the learning strategies answer the second round from
    // what the first taught them.
    for (int round = 0; round < 2; ++round) {
      std::vector<LocateResult> unary(queries.size());
      for (size_t i = 0; i < queries.size(); ++i) {
        ASSERT_TRUE(engine->Locate(queries[i], &unary[i]).ok());
      }
      std::vector<LocateResult> batch;
      ASSERT_TRUE(engine->LocateBatch(queries, &batch).ok());
      size_t wrong = 0;
      for (const auto& [how, got] :
           {std::pair{"Locate", &unary}, std::pair{"LocateBatch", &batch}}) {
        for (size_t i = 0; i < queries.size(); ++i) {
          if (!t.Agrees(queries[i], (*got)[i], want[i]) && ++wrong <= 5) {
            ADD_FAILURE() << how << " "
                          << test::DescribeAnswer(queries[i], (*got)[i])
                          << "; CGAL: "
                          << test::DescribeAnswer(queries[i], want[i]);
          }
        }
      }
      EXPECT_EQ(wrong, 0u) << "round " << round;
    }
  }
}

// The windmill centres (the loop's queries), every vertex and every edge
// midpoint (exact: integer corners; every mesh edge is constrained), and
// uniform points in and around the hull.
std::vector<Point2> QueriesFor(const Triangulation& t,
                               const std::vector<Point2>& centres,
                               size_t uniform) {
  std::vector<Point2> queries = centres;
  const std::vector<Point2> on_edges = test::ConstrainedEdgePoints(t);
  queries.insert(queries.end(), on_edges.begin(), on_edges.end());
  const BoundingBox box = t.bounding_box().Inflated(0.1);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> x(box.min_x, box.max_x);
  std::uniform_real_distribution<double> y(box.min_y, box.max_y);
  for (size_t i = 0; i < uniform; ++i)
    queries.push_back({x(random), y(random)});
  return queries;
}

TEST(WalkCycleTest, EveryStrategyTerminatesAndAgreesOnTheWindmill) {
  const Windmills w = MakeWindmills(1);
  ASSERT_NE(w.t, nullptr);
  // The centre many times over: every start the strategies pick gets it.
  std::vector<Point2> queries = QueriesFor(*w.t, w.centres, 2000);
  queries.insert(queries.end(), 500, w.centres[0]);
  ExpectEveryStrategyAgrees(w.mesh, *w.t, queries);
}

TEST(WalkCycleTest, EveryStrategyTerminatesAndAgreesOnTheTiledMesh) {
  const Windmills w = MakeWindmills(8);
  ASSERT_NE(w.t, nullptr);
  EXPECT_EQ(w.t->num_triangles(), w.mesh.constraints.triangles.size());
  std::vector<Point2> queries = QueriesFor(*w.t, w.centres, 4000);
  for (int copy = 0; copy < 20; ++copy) {
    queries.insert(queries.end(), w.centres.begin(), w.centres.end());
  }
  ExpectEveryStrategyAgrees(w.mesh, *w.t, queries);
}

}  // namespace
}  // namespace locator
