// locatord end to end on constrained datasets, one of each kind:
//   - a .poly terrain: a concave outer boundary (a bay cut into a square),
//     two holes marked by hole points, breaklines (one a polyline, one
//     ending on the outer boundary);
//   - a mesh served as given (.node + .ele): a grid stretched 16:1 with
//     random diagonals (not Delaunay), a hole and a notch left out;
//   - points plus WKT: a polygon with a bay and two holes, breaklines that
//     cross each other, the outer boundary and both holes' boundaries.
// For every kind and every strategy, locatord answers >= 10^4 queries over
// LocateBatch and over LocateStream, and a quarter of them over unary
// Locate (each strategy a different quarter, so that between them the four
// send every query unary too: 10^4 sequential unary calls take ~5 s in the
// ASAN tree, and Locate answers from the same engine call as the stream),
// each checked against CGAL's locate() on the same constrained
// triangulation plus the domain flag (Reference, in this process). The queries
// hold every dataset point, points exactly on every constrained edge and hole
// boundary (dyadic fractions along segments with integer ends), points inside
// the holes (which must answer OUTSIDE_DOMAIN and never a value), in the bay,
// beyond the hull, and uniform ones.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

constexpr size_t kBatchSize = 2500;
// Points inside a hole are queried on a grid of this many steps per side
// of its bounding box (exact: the corners are integers).
constexpr int kHoleSteps = 16;

const char* const kStrategies[] = {"walk", "jump-and-walk", "adaptive-paper",
                                   "self-tuning"};

using Polygon = std::vector<Point2>;

struct Segment {
  Point2 a, b;
};

// A dataset of one kind: its files, the spec that serves them, and what the
// queries are made from.
struct DomainDataset {
  std::vector<std::pair<std::string, std::string>> files;  // name, contents
  // The --dataset argument; "{dir}" stands for the files' directory.
  std::string spec;
  std::vector<Point2> points;
  // Every segment written as a constraint: boundaries and breaklines.
  std::vector<Segment> constrained;
  // Each constrained segment is queried at its k / along points, k =
  // 0..along (exact: the ends are integers).
  int along = 16;
  std::vector<Polygon> holes;
  BoundingBox box;
};

// The segments of the closed ring `ring`.
void AddRing(const Polygon& ring, std::vector<Segment>* segments) {
  for (size_t k = 0; k < ring.size(); ++k) {
    segments->push_back({ring[k], ring[(k + 1) % ring.size()]});
  }
}

// Twice the signed area of (a, b, q): exact for the small dyadic
// coordinates used here.
double Cross(const Point2& a, const Point2& b, const Point2& q) {
  return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
}

// The points of a kHoleSteps x kHoleSteps grid over the bounding box of the
// convex counter-clockwise polygon `hole` that are strictly inside it.
std::vector<Point2> PointsInside(const Polygon& hole) {
  BoundingBox box;
  for (const Point2& p : hole) box.Extend(p);
  std::vector<Point2> inside;
  for (int i = 1; i < kHoleSteps; ++i) {
    for (int j = 1; j < kHoleSteps; ++j) {
      const double x = box.min_x + box.width() * i / kHoleSteps;
      const double y = box.min_y + box.height() * j / kHoleSteps;
      bool strictly = true;
      for (size_t k = 0; k < hole.size(); ++k) {
        strictly &= Cross(hole[k], hole[(k + 1) % hole.size()], {x, y}) > 0;
      }
      if (strictly) inside.push_back({x, y});
    }
  }
  return inside;
}

// `n` uniform points in [0, side]^2, with 17 significant digits in files.
std::vector<Point2> UniformPoints(size_t n, double side, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, side);
  std::vector<Point2> points;
  for (size_t i = 0; i < n; ++i) points.push_back({u(random), u(random)});
  return points;
}

std::string Number(double v) {
  std::ostringstream text;
  text.precision(17);
  text << v;
  return text.str();
}

// Terrain.poly: the integer grid on [0, 40]^2 plus 1500 uniform points, all
// with value TestValue. The domain is the square [2, 38]^2 with a bay cut
// in from the top edge down to (20, 24); the segment (38, 38)-(20, 24)
// passes through the grid point (29, 31). Two holes (a square and a
// triangle) carry hole points; a polyline and a segment are breaklines, and
// a third breakline ends on the outer boundary at (2, 28).
DomainDataset TerrainPoly() {
  DomainDataset d;
  constexpr int kSide = 40;
  for (int y = 0; y <= kSide; ++y) {
    for (int x = 0; x <= kSide; ++x) d.points.push_back({1.0 * x, 1.0 * y});
  }
  const std::vector<Point2> scattered = UniformPoints(1500, kSide, 3);
  d.points.insert(d.points.end(), scattered.begin(), scattered.end());
  // Grid point (x, y) has index y * 41 + x, numbered from 1 in the file.
  const auto index = [](const Point2& p) {
    return static_cast<int>(p.y) * (kSide + 1) + static_cast<int>(p.x) + 1;
  };
  const Polygon outer = {{2, 2}, {38, 2}, {38, 38}, {20, 24}, {2, 38}};
  d.holes = {{{8, 8}, {14, 8}, {14, 14}, {8, 14}},
             {{24, 6}, {34, 6}, {30, 16}}};
  const std::vector<Point2> hole_points = {{11, 11}, {30, 9}};
  for (const Polygon& ring : {outer, d.holes[0], d.holes[1]}) {
    AddRing(ring, &d.constrained);
  }
  for (const Segment& s : std::vector<Segment>{{{5, 16}, {10, 22}},
                                               {{10, 22}, {16, 21}},
                                               {{22, 20}, {36, 23}},
                                               {{2, 28}, {8, 26}}}) {
    d.constrained.push_back(s);
  }
  std::ostringstream poly;
  poly << d.points.size() << " 2 1 0\n";
  for (size_t i = 0; i < d.points.size(); ++i) {
    poly << i + 1 << " " << Number(d.points[i].x) << " "
         << Number(d.points[i].y) << " " << Number(TestValue(d.points[i]))
         << "\n";
  }
  poly << d.constrained.size() << " 0\n";
  for (size_t k = 0; k < d.constrained.size(); ++k) {
    poly << k + 1 << " " << index(d.constrained[k].a) << " "
         << index(d.constrained[k].b) << "\n";
  }
  poly << hole_points.size() << "\n";
  for (size_t k = 0; k < hole_points.size(); ++k) {
    poly << k + 1 << " " << hole_points[k].x << " " << hole_points[k].y << "\n";
  }
  d.files = {{"terrain.poly", poly.str()}};
  d.spec = "{dir}/terrain.poly";
  d.box = {0, 0, kSide, kSide};
  return d;
}

// Mesh.node + mesh.ele: nodes (16 i, j) for i = 0..30, j = 0..24 with value
// TestValue; each grid cell split by a random diagonal, except the cells of
// a hole (i in 8..12, j in 6..11) and of a notch at the top right corner
// (i >= 22, j >= 16), whose nodes stay unused.
DomainDataset StretchedMesh() {
  DomainDataset d;
  constexpr int kColumns = 30, kRows = 24;
  constexpr double kStretch = 16;
  for (int j = 0; j <= kRows; ++j) {
    for (int i = 0; i <= kColumns; ++i) {
      d.points.push_back({kStretch * i, 1.0 * j});
    }
  }
  const auto node = [](int i, int j) { return j * (kColumns + 1) + i + 1; };
  std::mt19937_64 random(9);
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j < kRows; ++j) {
    for (int i = 0; i < kColumns; ++i) {
      const bool diagonal_up = random() & 1;
      const bool hole = i >= 8 && i < 13 && j >= 6 && j < 12;
      const bool notch = i >= 22 && j >= 16;
      if (hole || notch) continue;
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1),
                e = node(i, j + 1);
      if (diagonal_up) {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, e});
        d.constrained.push_back({d.points[a - 1], d.points[c - 1]});
      } else {
        triangles.push_back({a, b, e});
        triangles.push_back({b, c, e});
        d.constrained.push_back({d.points[b - 1], d.points[e - 1]});
      }
    }
  }
  const auto at = [&](int i, int j) { return Point2{kStretch * i, 1.0 * j}; };
  d.holes = {{at(8, 6), at(13, 6), at(13, 12), at(8, 12)}};
  AddRing(d.holes[0], &d.constrained);
  AddRing({at(22, 16), at(30, 16), at(30, 24), at(22, 24)}, &d.constrained);
  AddRing({at(0, 0), at(30, 0), at(30, 24), at(0, 24)}, &d.constrained);
  std::ostringstream nodes;
  nodes << d.points.size() << " 2 1 0\n";
  for (size_t i = 0; i < d.points.size(); ++i) {
    nodes << i + 1 << " " << d.points[i].x << " " << d.points[i].y << " "
          << TestValue(d.points[i]) << "\n";
  }
  std::ostringstream ele;
  ele << triangles.size() << " 3 0\n";
  for (size_t k = 0; k < triangles.size(); ++k) {
    ele << k + 1 << " " << triangles[k][0] << " " << triangles[k][1] << " "
        << triangles[k][2] << "\n";
  }
  d.files = {{"mesh.node", nodes.str()}, {"mesh.ele", ele.str()}};
  d.along = 4;
  d.spec = "{dir}/mesh.ele";
  d.box = {0, 0, kStretch * kColumns, kRows};
  return d;
}

// `ring` as WKT coordinates "x y z, ..." with z = TestValue, closed.
std::string WktRing(const Polygon& ring) {
  std::string text;
  for (size_t k = 0; k <= ring.size(); ++k) {
    const Point2& p = ring[k % ring.size()];
    text += (k > 0 ? ", " : "") + Number(p.x) + " " + Number(p.y) + " " +
            Number(TestValue(p));
  }
  return text;
}

// Points.csv + constraints.wkt: the grid of pitch 5 on [0, 100]^2 plus 2500
// uniform points, values TestValue. One POLYGON Z: a square with a bay down
// to (50, 60) and two holes; LINESTRING Z breaklines crossing each other at
// (27.5, 65), one leaving the domain through the bay's edge, one crossing
// the square hole at (20, 30) and (40, 30) (grid points on its boundary),
// one crossing the triangular hole's boundary where no point is.
DomainDataset PointsPlusWkt() {
  DomainDataset d;
  constexpr int kSide = 100;
  for (int y = 0; y <= kSide; y += 5) {
    for (int x = 0; x <= kSide; x += 5) d.points.push_back({1.0 * x, 1.0 * y});
  }
  const std::vector<Point2> scattered = UniformPoints(2500, kSide, 4);
  d.points.insert(d.points.end(), scattered.begin(), scattered.end());
  const Polygon outer = {{5, 5}, {95, 5}, {95, 95}, {50, 60}, {5, 95}};
  d.holes = {{{20, 20}, {40, 20}, {40, 40}, {20, 40}},
             {{60, 20}, {80, 20}, {70, 40}}};
  for (const Polygon& ring : {outer, d.holes[0], d.holes[1]}) {
    AddRing(ring, &d.constrained);
  }
  const std::vector<Segment> breaklines = {{{10, 50}, {45, 80}},
                                           {{10, 80}, {45, 50}},
                                           {{15, 30}, {45, 30}},
                                           {{55, 25}, {85, 35}}};
  d.constrained.insert(d.constrained.end(), breaklines.begin(),
                       breaklines.end());
  std::string csv = "x,y,z\n";
  for (const Point2& p : d.points) {
    csv += Number(p.x) + "," + Number(p.y) + "," + Number(TestValue(p)) + "\n";
  }
  std::string wkt = "POLYGON Z ((" + WktRing(outer) + "),\n  (" +
                    WktRing(d.holes[0]) + "),\n  (" + WktRing(d.holes[1]) +
                    "))\n";
  for (const Segment& s : breaklines) {
    wkt += "LINESTRING Z (" + Number(s.a.x) + " " + Number(s.a.y) + " " +
           Number(TestValue(s.a)) + ", " + Number(s.b.x) + " " + Number(s.b.y) +
           " " + Number(TestValue(s.b)) + ")\n";
  }
  d.files = {{"points.csv", csv}, {"constraints.wkt", wkt}};
  d.spec = "{dir}/points.csv+{dir}/constraints.wkt";
  d.box = {0, 0, kSide, kSide};
  return d;
}

// The queries for `d`, >= 10^4: every dataset point, d.along + 1 points on
// every constrained segment, the points inside the holes, uniform points
// over the box grown by a tenth (some beyond the hull), points on the box's
// edge lines beyond it, and far away.
std::vector<Point2> QueriesFor(const DomainDataset& d,
                               const std::vector<Point2>& in_holes) {
  std::vector<Point2> queries = d.points;
  for (const Segment& s : d.constrained) {
    for (int k = 0; k <= d.along; ++k) {
      const double t = static_cast<double>(k) / d.along;
      queries.push_back(
          {s.a.x + t * (s.b.x - s.a.x), s.a.y + t * (s.b.y - s.a.y)});
    }
  }
  queries.insert(queries.end(), in_holes.begin(), in_holes.end());
  const BoundingBox grown = d.box.Inflated(0.1);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> x(grown.min_x, grown.max_x);
  std::uniform_real_distribution<double> y(grown.min_y, grown.max_y);
  while (queries.size() < 10'500) queries.push_back({x(random), y(random)});
  for (int k = 1; k <= 50; ++k) {
    const double beyond = k * 0.05 * d.box.width();
    queries.push_back({d.box.min_x - beyond, d.box.min_y});
    queries.push_back({d.box.max_x, d.box.max_y + beyond});
    queries.push_back({d.box.max_x + beyond, y(random)});
  }
  queries.push_back({-1e300, 1e300});
  return queries;
}

// A kind's files in a directory of their own, its CGAL reference, its
// queries and CGAL's answers to them: made once per test process.
struct ServedKind {
  ScratchDir dir;
  std::string spec;
  std::unique_ptr<Reference> reference;
  std::vector<Point2> queries;
  std::vector<LocateResult> wants;  // reference->Locate(queries[i])
  std::vector<Point2> in_holes;
  size_t holes = 0;
};

std::unique_ptr<ServedKind> Serve(const DomainDataset& d) {
  auto kind = std::make_unique<ServedKind>();
  for (const auto& [name, contents] : d.files) {
    std::ofstream(kind->dir.path() + "/" + name, std::ios::binary) << contents;
  }
  kind->spec = d.spec;
  for (size_t at = kind->spec.find("{dir}"); at != std::string::npos;
       at = kind->spec.find("{dir}")) {
    kind->spec.replace(at, 5, kind->dir.path());
  }
  const Status built = Reference::Build(kind->spec, &kind->reference);
  EXPECT_TRUE(built.ok()) << built.ToString();
  for (const Polygon& hole : d.holes) {
    const std::vector<Point2> inside = PointsInside(hole);
    kind->in_holes.insert(kind->in_holes.end(), inside.begin(), inside.end());
  }
  kind->queries = QueriesFor(d, kind->in_holes);
  if (kind->reference != nullptr) {
    kind->wants = kind->reference->LocateAll(kind->queries);
  }
  kind->holes = d.holes.size();
  return kind;
}

// Every kStrategies-th query and CGAL's answer to it, from the strategy's
// index on: the unary share of the strategy `strategy`.
void UnaryShare(const ServedKind& kind, std::string_view strategy,
                std::vector<Point2>* queries,
                std::vector<LocateResult>* wants) {
  const size_t strategies = std::size(kStrategies);
  const size_t first =
      std::find(std::begin(kStrategies), std::end(kStrategies), strategy) -
      std::begin(kStrategies);
  for (size_t i = first; i < kind.queries.size(); i += strategies) {
    queries->push_back(kind.queries[i]);
    wants->push_back(kind.wants[i]);
  }
}

class LocatordDomainTest : public ::testing::TestWithParam<const char*> {
 protected:
  static void TearDownTestSuite() { kinds_.clear(); }

  // The kind `make` makes, served once per process (ctest runs every test
  // in a process of its own, so each builds only the kind it needs).
  static const ServedKind& Kind(DomainDataset (*make)()) {
    std::unique_ptr<ServedKind>& kind = kinds_[make];
    if (kind == nullptr) kind = Serve(make());
    return *kind;
  }

  // Serves `kind` with this test's strategy, and checks every answer over
  // unary, batch and stream against CGAL, the holes' answers, and the
  // domain in GetStats.
  void ExpectServedAsCgalLocates(const ServedKind& kind) {
    ASSERT_NE(kind.reference, nullptr);
    const Reference& reference = *kind.reference;
    const std::vector<Point2>& queries = kind.queries;
    ASSERT_GE(queries.size(), 10'000u);
    // The queries reach every location type, in numbers.
    size_t by_type[5] = {};
    for (const LocateResult& want : kind.wants) {
      ++by_type[static_cast<int>(want.type)];
    }
    for (size_t count : by_type) EXPECT_GE(count, 100u);

    std::unique_ptr<ServerProcess> server;
    const Status started = StartLocatord(kind.spec,
                                         {"--strategy", GetParam(), "--warmup",
                                          "1000", "--retune-every", "1000"},
                                         &server);
    ASSERT_TRUE(started.ok()) << started.ToString();
    auto stub = NewStub(*server);

    std::vector<Point2> unary_queries;
    std::vector<LocateResult> unary_wants;
    UnaryShare(kind, GetParam(), &unary_queries, &unary_wants);
    EXPECT_EQ(
        reference.Disagreements(unary_queries, LocateEach(*stub, unary_queries),
                                unary_wants, true),
        "")
        << "unary";
    EXPECT_EQ(reference.Disagreements(
                  queries, LocateInBatches(*stub, queries, kBatchSize),
                  kind.wants, false),
              "")
        << "batch";
    EXPECT_EQ(reference.Disagreements(queries, LocateOverStream(*stub, queries),
                                      kind.wants, true),
              "")
        << "stream";

    // Inside a hole: OUTSIDE_DOMAIN and no value, however it was asked.
    const std::vector<LocateResult> hole_answers[] = {
        LocateEach(*stub, kind.in_holes),
        LocateInBatches(*stub, kind.in_holes, kBatchSize),
        LocateOverStream(*stub, kind.in_holes)};
    for (const std::vector<LocateResult>& answers : hole_answers) {
      ASSERT_EQ(answers.size(), kind.in_holes.size());
      for (size_t i = 0; i < answers.size(); ++i) {
        EXPECT_EQ(answers[i].type, LocationType::kOutsideDomain)
            << kind.in_holes[i].x << ", " << kind.in_holes[i].y;
        EXPECT_FALSE(answers[i].has_value);
      }
    }

    const v1::GetStatsResponse stats = GetStats(*stub);
    EXPECT_EQ(stats.strategy(), GetParam());
    EXPECT_EQ(stats.dataset().holes(), kind.holes);
    EXPECT_GT(stats.dataset().constraints(), 0u);
    EXPECT_LT(stats.dataset().triangles(), stats.dataset().all_triangles());
    EXPECT_EQ(
        stats.queries_served(),
        unary_queries.size() + 2 * queries.size() + 3 * kind.in_holes.size());
  }

 private:
  static std::map<DomainDataset (*)(), std::unique_ptr<ServedKind>> kinds_;
};

std::map<DomainDataset (*)(), std::unique_ptr<ServedKind>>
    LocatordDomainTest::kinds_;

TEST_P(LocatordDomainTest, PolyTerrainWithHolesAndBreaklines) {
  ExpectServedAsCgalLocates(Kind(TerrainPoly));
}

TEST_P(LocatordDomainTest, NonDelaunayMeshServedAsGiven) {
  ExpectServedAsCgalLocates(Kind(StretchedMesh));
}

TEST_P(LocatordDomainTest, PointsPlusWktWithBreaklinesAndHoles) {
  ExpectServedAsCgalLocates(Kind(PointsPlusWkt));
}

INSTANTIATE_TEST_SUITE_P(Strategies, LocatordDomainTest,
                         ::testing::ValuesIn(kStrategies),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace locator::test
