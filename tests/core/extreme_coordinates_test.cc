// No finite double crashes the engine or spoils an answer: datasets at
// every scale a double has (denormals to DBL_MAX, and mixed), queried with
// every extreme coordinate through Locate, LocateBatch, the three
// interpolations, profiles and rasters. An answer for a finite query agrees
// with CGAL's locate() on the same triangulation and carries only finite
// numbers; a non-finite query, and a line or raster whose numbers would
// not be doubles, is refused with InvalidArgument saying why.
//
// The scaled datasets are one integer dataset times 2^k, so their answers
// can also be checked against each other: exact predicates do not see a
// power-of-two scale, and values are a plane in the unscaled coordinates.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/input_text.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "locator/raster.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/geometry/wide_math.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using L = std::numeric_limits<double>;
constexpr double kMax = L::max();
constexpr const char* kStrategies[] = {"walk", "jump-and-walk",
                                       "adaptive-paper", "self-tuning"};

// The coordinates every query field is drawn from: zeros, denormals, the
// smallest normal, and magnitudes where squares and products of
// differences leave the doubles (1e-300, 1e150, 1e160, 1e300, DBL_MAX).
const std::vector<double>& FiniteExtremes() {
  static const auto* values = new std::vector<double>{0.0,
                                                      -0.0,
                                                      L::denorm_min(),
                                                      -L::denorm_min(),
                                                      L::min(),
                                                      1e-300,
                                                      -1e-300,
                                                      1e150,
                                                      -1e150,
                                                      1e160,
                                                      -1e160,
                                                      1e300,
                                                      -1e300,
                                                      kMax,
                                                      -kMax};
  return *values;
}
constexpr double kNonFinite[] = {L::quiet_NaN(), L::infinity(), -L::infinity()};

// Every pair of FiniteExtremes().
std::vector<Point2> ExtremeQueries() {
  std::vector<Point2> queries;
  for (const double x : FiniteExtremes()) {
    for (const double y : FiniteExtremes()) queries.push_back({x, y});
  }
  return queries;
}

// An integer dataset to scale: a 5 x 5 grid (cocircular ties) of spacing
// 2^20, 150 random points within 2^21 and four corners at +-(2^53 - 1), so
// that 2^971 times it reaches +-DBL_MAX and 2^-1074 times it is all
// denormals and small normals, every coordinate exact.
std::vector<Point2> IntegerPoints() {
  std::vector<Point2> points;
  for (int i = -2; i <= 2; ++i) {
    for (int j = -2; j <= 2; ++j) points.push_back({i * 0x1p20, j * 0x1p20});
  }
  std::mt19937_64 rng(26);
  std::uniform_int_distribution<int64_t> coordinate(-(1 << 21), 1 << 21);
  for (int k = 0; k < 150; ++k) {
    points.push_back({double(coordinate(rng)), double(coordinate(rng))});
  }
  constexpr double kCorner = 0x1p53 - 1;
  for (const double sx : {-kCorner, kCorner}) {
    for (const double sy : {-kCorner, kCorner}) points.push_back({sx, sy});
  }
  return points;
}

// The plane the scaled datasets' values lie on, in unscaled units (so the
// same at every scale): 2u + 3v + 1 with u = x / 2^(53 + k), v likewise.
double ScaledPlane(const Point2& p, int k) {
  return 2 * std::ldexp(p.x, -53 - k) + 3 * std::ldexp(p.y, -53 - k) + 1;
}

Dataset ScaledDataset(int k) {
  Dataset ds;
  for (const Point2& p : IntegerPoints()) {
    ds.points.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
    ds.values.push_back(ScaledPlane(ds.points.back(), k));
  }
  ds.source = "scaled-2^" + std::to_string(k);
  return ds;
}

// A number of random sign and magnitude 10^e, e uniform in [lo, hi].
double LogUniform(std::mt19937_64& rng, double lo, double hi) {
  const double v =
      std::pow(10.0, std::uniform_real_distribution<>(lo, hi)(rng));
  return std::bernoulli_distribution()(rng) ? v : -v;
}

// Points at magnitudes from 1e-300 to 1e300 at once, the corners at
// +-DBL_MAX, and values anywhere in +-DBL_MAX (some exactly).
Dataset MixedDataset() {
  Dataset ds;
  std::mt19937_64 rng(27);
  for (int k = 0; k < 200; ++k) {
    ds.points.push_back(
        {LogUniform(rng, -300, 300), LogUniform(rng, -300, 300)});
  }
  for (const double sx : {-kMax, kMax}) {
    for (const double sy : {-kMax, kMax}) ds.points.push_back({sx, sy});
  }
  ds.points.push_back({0, 0});
  for (size_t i = 0; i < ds.points.size(); ++i) {
    ds.values.push_back(i % 3 == 0   ? (i % 2 ? kMax : -kMax)
                        : i % 3 == 1 ? LogUniform(rng, 250, 308)
                                     : LogUniform(rng, -300, 300));
  }
  ds.source = "mixed";
  return ds;
}

// Whether v lies in [lo, hi], up to the rounding of a combination of
// values with barycentrics (each right to 2^-40) or weights.
bool Between(double v, double lo, double hi) {
  const double slack = 1e-10 * std::max(std::abs(lo), std::abs(hi));
  return std::isfinite(v) && v >= lo - slack && v <= hi + slack;
}

// The values that `ds` has, lowest and highest.
std::pair<double, double> ValueRange(const Dataset& ds) {
  const auto [lo, hi] = std::minmax_element(ds.values.begin(), ds.values.end());
  return {*lo, *hi};
}

// One dataset with its engines (one per strategy, re-tuning often so that
// the tuners run on its box) and CGAL's triangulation of it.
struct Served {
  Dataset dataset;
  std::unique_ptr<Triangulation> t;
  std::vector<std::unique_ptr<Engine>> engines;
  // The value of every vertex by its id (crossings of constraints too).
  std::vector<double> value_of_id;

  const Engine& engine() const { return *engines.back(); }  // self-tuning
};

std::unique_ptr<Served> Serve(Dataset dataset) {
  auto served = std::make_unique<Served>();
  served->dataset = std::move(dataset);
  served->t = test::BuildTriangulation(served->dataset);
  if (served->t == nullptr) return nullptr;
  const ServingMesh& mesh = served->t->mesh();
  served->value_of_id.resize(mesh.id_bound());
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.has_values()) {
      served->value_of_id[mesh.PublicId(v)] = mesh.arrays().values[v];
    }
  }
  for (const char* strategy : kStrategies) {
    EngineOptions options;
    options.strategy = strategy;
    options.tuning.warmup_queries = 64;
    options.tuning.retune_every = 64;
    StatusOr<std::unique_ptr<Engine>> engine =
        Engine::Create(served->dataset, options);
    EXPECT_TRUE(engine.ok()) << strategy << ": " << engine.status().ToString();
    if (!engine.ok()) return nullptr;
    served->engines.push_back(*std::move(engine));
  }
  return served;
}

// The queries for a dataset: ExtremeQueries(), its points, the midpoints of
// its edges (on an edge where representable) and points spread over its box.
std::vector<Point2> QueriesFor(const Served& s) {
  std::vector<Point2> queries = ExtremeQueries();
  const auto& dt = s.t->cgal();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Point2 a =
        Triangulation::FromCgal(e->first->vertex(dt.ccw(e->second))->point());
    const Point2 b =
        Triangulation::FromCgal(e->first->vertex(dt.cw(e->second))->point());
    queries.push_back(a);
    queries.push_back(Midpoint(a, b));
  }
  const BoundingBox& box = s.t->bounding_box();
  std::mt19937_64 rng(28);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 200; ++k) {
    queries.push_back({Lerp(box.min_x, box.max_x, unit(rng)),
                       Lerp(box.min_y, box.max_y, unit(rng))});
  }
  return queries;
}

// Every n-th of `all`.
std::vector<Point2> EveryNth(const std::vector<Point2>& all, size_t n) {
  std::vector<Point2> some;
  for (size_t i = 0; i < all.size(); i += n) some.push_back(all[i]);
  return some;
}

bool AllFinite(const LocateResult& r) {
  for (int i = 0; i < 3; ++i) {
    if (!IsFinite(r.vertices[i]) || !std::isfinite(r.barycentric[i])) {
      return false;
    }
  }
  return std::isfinite(r.value);
}

// The checks every answer for a finite q passes: agreement with CGAL, only
// finite numbers, and a linear value between its triangle's corner values.
void ExpectRightAnswer(const Served& s, const Point2& q,
                       const LocateResult& got, const char* strategy) {
  const LocateResult want = s.t->ReferenceLocate(q);
  EXPECT_TRUE(s.t->Agrees(q, got, want))
      << strategy << ": " << test::DescribeAnswer(q, got) << " but CGAL says "
      << test::DescribeAnswer(q, want);
  EXPECT_TRUE(AllFinite(got))
      << strategy << ": " << test::DescribeAnswer(q, got);
  if (!got.has_value) return;
  double lo = kMax, hi = -kMax;
  for (int i = 0; i < 3; ++i) {
    const double v = s.value_of_id[got.vertex_ids[i]];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_TRUE(Between(got.value, lo, hi))
      << got.value << " not in [" << lo << ", " << hi << "] at "
      << test::DescribeAnswer(q, got);
}

// Locate and LocateBatch on every strategy, re-tuned on these queries:
// finite queries answer as CGAL does, non-finite ones are refused naming
// the point.
void ExpectLocatesRight(const Served& s, const std::vector<Point2>& queries) {
  for (size_t e = 0; e < s.engines.size(); ++e) {
    Engine& engine = *s.engines[e];
    const char* strategy = kStrategies[e];
    std::vector<LocateResult> singles(queries.size());
    for (size_t i = 0; i < queries.size(); ++i) {
      ASSERT_TRUE(engine.Locate(queries[i], &singles[i]).ok());
      ExpectRightAnswer(s, queries[i], singles[i], strategy);
    }
    engine.Retune();
    std::vector<LocateResult> batch;
    ASSERT_TRUE(engine.LocateBatch(queries, &batch).ok());
    for (size_t i = 0; i < queries.size(); ++i) {
      ExpectRightAnswer(s, queries[i], batch[i], strategy);
    }
    for (const double bad : kNonFinite) {
      for (const Point2& q :
           {Point2{bad, 0}, Point2{0, bad}, Point2{bad, bad}}) {
        LocateResult r;
        const Status single = engine.Locate(q, &r);
        EXPECT_EQ(single.code(), Status::Code::kInvalidArgument);
        EXPECT_NE(single.message().find("non-finite"), std::string::npos)
            << single.message();
        const std::vector<Point2> with_bad = {queries[0], q};
        const Status many = engine.LocateBatch(with_bad, &batch);
        EXPECT_EQ(many.code(), Status::Code::kInvalidArgument);
        EXPECT_NE(many.message().find("point 1 "), std::string::npos)
            << many.message();
      }
    }
  }
}

// The value of the corner of r's triangle nearest q (distances exact enough
// in Wide), or of any corner at that distance.
bool IsNearestCornerValue(const Served& s, const Point2& q,
                          const LocateResult& r, double value) {
  Wide best = -1;
  for (int i = 0; i < 3; ++i) {
    const Wide d = SquaredDistanceWide(r.vertices[i], q);
    if (best < 0 || d < best) best = d;
  }
  for (int i = 0; i < 3; ++i) {
    if (SquaredDistanceWide(r.vertices[i], q) == best &&
        s.value_of_id[r.vertex_ids[i]] == value) {
      return true;
    }
  }
  return false;
}

// Natural-neighbour and nearest values at every finite query: finite and
// within the dataset's values; nearest is the nearest corner's; where the
// values lie on a plane (`plane`, if given), linear and natural-neighbour
// interpolation reproduce it.
void ExpectInterpolationsRight(const Served& s,
                               const std::vector<Point2>& queries,
                               double (*plane)(const Point2&, int), int k) {
  const Engine& engine = s.engine();
  const auto [lo, hi] = ValueRange(s.dataset);
  for (const Point2& q : queries) {
    LocateResult linear, natural, nearest;
    ASSERT_TRUE(engine.Locate(q, &linear).ok());
    ASSERT_TRUE(
        engine.Locate(q, &natural, Interpolation::kNaturalNeighbor).ok());
    ASSERT_TRUE(engine.Locate(q, &nearest, Interpolation::kNearest).ok());
    ASSERT_EQ(natural.has_value, linear.has_value);
    ASSERT_EQ(nearest.has_value, linear.has_value);
    if (!linear.has_value) continue;
    const std::string where = test::DescribeAnswer(q, linear);
    for (const double v : {linear.value, natural.value, nearest.value}) {
      EXPECT_TRUE(Between(v, lo, hi)) << v << " " << where;
    }
    EXPECT_TRUE(IsNearestCornerValue(s, q, nearest, nearest.value)) << where;
    if (plane != nullptr) {
      EXPECT_NEAR(linear.value, plane(q, k), 1e-9) << where;
      EXPECT_NEAR(natural.value, plane(q, k), 1e-9) << where;
    }
  }
}

// Whether p lies in the box of the segment ab (ends included).
bool InSegmentBox(const Point2& p, const Point2& a, const Point2& b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) &&
         p.y >= std::min(a.y, b.y) && p.y <= std::max(a.y, b.y);
}

// Traces `line` on every interpolation and checks what holds for any
// profile: every number finite; breakpoints in order along the line, each
// on its segment; mesh vertices exactly dataset points; values within the
// dataset's; the line's own vertices valued as Locate values them. A line
// longer than the largest double is refused saying so. The linear profile
// goes to *linear (empty when refused). Natural neighbour only if
// `natural`: over needles it may take exact rationals, milliseconds a point.
void ExpectProfileRight(const Served& s, const std::vector<Point2>& line,
                        Profile* linear, bool natural = true) {
  const Engine& engine = s.engine();
  const auto [lo, hi] = ValueRange(s.dataset);
  Wide length = 0;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    length += Distance(line[i], line[i + 1]);
  }
  std::set<std::pair<double, double>> points;
  for (const Point2& p : s.dataset.points) points.insert({p.x, p.y});
  *linear = Profile();
  for (const Interpolation how :
       {Interpolation::kLinear, Interpolation::kNaturalNeighbor,
        Interpolation::kNearest}) {
    if (how == Interpolation::kNaturalNeighbor && !natural) continue;
    ProfileOptions options;
    options.samples = 9;
    options.interpolation = how;
    Profile profile;
    const Status status = engine.TraceProfile(line, options, &profile);
    const std::string what =
        "line from " + PointText(line[0]) + " to " + PointText(line.back());
    if (length > kMaxDouble) {
      EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << what;
      EXPECT_NE(status.message().find("longer than the largest double"),
                std::string::npos)
          << status.message();
      continue;
    }
    ASSERT_TRUE(status.ok()) << what << ": " << status.ToString();
    ASSERT_FALSE(profile.breakpoints.empty());
    EXPECT_TRUE(std::isfinite(profile.length)) << what;
    const ProfilePoint& first = profile.breakpoints.front();
    EXPECT_EQ(first.distance, 0);
    EXPECT_EQ(first.kind, ProfilePointKind::kLineVertex);
    EXPECT_EQ(profile.breakpoints.back().distance, profile.length);
    double previous = 0;
    for (const ProfilePoint& b : profile.breakpoints) {
      EXPECT_TRUE(IsFinite(b.point) && std::isfinite(b.distance)) << what;
      EXPECT_GE(b.distance, previous) << what;
      previous = b.distance;
      ASSERT_LT(b.segment + 1, line.size());
      EXPECT_TRUE(InSegmentBox(b.point, line[b.segment], line[b.segment + 1]))
          << what << ": breakpoint " << b.point.x << " " << b.point.y;
      if (b.kind == ProfilePointKind::kMeshVertex) {
        EXPECT_TRUE(points.contains({b.point.x, b.point.y})) << what;
      }
      if (b.has_value) {
        EXPECT_TRUE(Between(b.value, lo, hi)) << what << ": value " << b.value;
      }
      if (b.kind == ProfilePointKind::kLineVertex &&
          how == Interpolation::kLinear) {
        LocateResult r;
        ASSERT_TRUE(engine.Locate(b.point, &r).ok());
        EXPECT_EQ(b.has_value, r.has_value) << what;
        if (b.has_value && r.has_value) {
          EXPECT_NEAR(b.value, r.value, 1e-9 * std::max(1.0, std::abs(r.value)))
              << what;
        }
      }
    }
    EXPECT_EQ(profile.samples.size(), 9u);
    for (const ProfilePoint& p : profile.samples) {
      EXPECT_TRUE(IsFinite(p.point) && std::isfinite(p.distance)) << what;
      EXPECT_GE(p.distance, 0);
      EXPECT_LE(p.distance, profile.length);
      if (p.has_value) {
        EXPECT_TRUE(Between(p.value, lo, hi))
            << what << ": sample value " << p.value;
      }
    }
    for (const ProfileGap& gap : profile.gaps) {
      EXPECT_TRUE(std::isfinite(gap.from_distance) &&
                  std::isfinite(gap.to_distance));
      EXPECT_LE(gap.from_distance, gap.to_distance);
    }
    if (how == Interpolation::kLinear) *linear = std::move(profile);
  }
}

// Lines between extreme points: the issue's +-1e160 diagonal, +-DBL_MAX
// diagonals (longer than a double), lines through the dataset's corners and
// between random pairs of extreme points, one with a repeated vertex.
std::vector<std::vector<Point2>> ExtremeLines(const Served& s) {
  const BoundingBox& box = s.t->bounding_box();
  std::vector<std::vector<Point2>> lines = {
      {{-1e160, -1e160}, {1e160, 1e160}},
      {{-kMax, -kMax}, {kMax, kMax}},
      {{-1e308, 0}, {1e308, 0}},
      {{0, -kMax / 2}, {0, kMax / 2}},
      {{box.min_x, box.min_y}, {box.max_x, box.max_y}},
      {{box.min_x, box.max_y},
       {box.max_x, box.min_y},
       {box.max_x, box.min_y},
       {Midpoint({box.min_x, box.min_y}, {box.max_x, box.max_y})}},
  };
  const std::vector<Point2> extremes = ExtremeQueries();
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<size_t> pick(0, extremes.size() - 1);
  for (int k = 0; k < 30; ++k) {
    lines.push_back(
        {extremes[pick(rng)], extremes[pick(rng)], extremes[pick(rng)]});
  }
  return lines;
}

// Renders `spec` on the self-tuning engine and checks each cell against
// Locate at its centre: nodata exactly where Locate has no value, else the
// same value (to rounding); every centre finite and inside the box.
void ExpectRasterRight(const Served& s, RasterSpec spec) {
  const Engine& engine = s.engine();
  spec.nodata = -12345;
  std::vector<double> cells(spec.cells());
  ASSERT_TRUE(engine.RenderRows(spec, 0, spec.height, cells.data()).ok());
  for (uint32_t row = 0; row < spec.height; ++row) {
    for (uint32_t col = 0; col < spec.width; ++col) {
      const Point2 q = spec.CellCentre(col, row);
      ASSERT_TRUE(IsFinite(q) && spec.box.Contains(q)) << col << " " << row;
      LocateResult r;
      ASSERT_TRUE(engine.Locate(q, &r).ok());
      const double cell = cells[size_t{row} * spec.width + col];
      if (!r.has_value) {
        EXPECT_EQ(cell, spec.nodata) << test::DescribeAnswer(q, r);
      } else {
        EXPECT_NEAR(cell, r.value, 1e-9 * std::max(1.0, std::abs(r.value)))
            << test::DescribeAnswer(q, r);
      }
    }
  }
}

// Rasters over the dataset's box, over all the doubles, and around its
// centre; a raster whose one cell would be wider than a double is refused.
void ExpectRastersRight(const Served& s) {
  const BoundingBox& box = s.t->bounding_box();
  ExpectRasterRight(s, RasterSpec{.box = box, .width = 13, .height = 7});
  ExpectRasterRight(
      s,
      RasterSpec{.box = {-kMax, -kMax, kMax, kMax}, .width = 8, .height = 5});
  const BoundingBox around{
      Lerp(box.min_x, box.max_x, 0.45), Lerp(box.min_y, box.max_y, 0.45),
      Lerp(box.min_x, box.max_x, 0.55), Lerp(box.min_y, box.max_y, 0.55)};
  ExpectRasterRight(s, RasterSpec{.box = around, .width = 6, .height = 6});
  std::vector<double> cells(1);
  const Status wide = s.engine().RenderRows(
      RasterSpec{.box = {-kMax, 0, kMax, 1}, .width = 1, .height = 1}, 0, 1,
      cells.data());
  EXPECT_EQ(wide.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(wide.message().find("not representable"), std::string::npos)
      << wide.message();
}

// The scaled datasets, by their exponent k (2^k times IntegerPoints()):
// denormals, ~1e-300, unscaled, ~1e150, ~1e290 and up to +-DBL_MAX.
constexpr int kScales[] = {-1074, -1000, 0, 450, 900, 971};

const Served& ScaledServed(int k) {
  static auto* served = new std::map<int, std::unique_ptr<Served>>;
  auto& slot = (*served)[k];
  if (slot == nullptr) slot = Serve(ScaledDataset(k));
  return *slot;
}

class ScaledTest : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    served_ = &ScaledServed(GetParam());
    ASSERT_NE(served_->t, nullptr);
  }
  const Served& s() const { return *served_; }
  int k() const { return GetParam(); }

 private:
  const Served* served_ = nullptr;
};

TEST_P(ScaledTest, LocatesAgreeWithCgal) {
  ExpectLocatesRight(s(), QueriesFor(s()));
}

TEST_P(ScaledTest, InterpolationsReproduceThePlane) {
  ExpectInterpolationsRight(s(), QueriesFor(s()), ScaledPlane, k());
}

TEST_P(ScaledTest, ExtremeProfilesAreRightOrRefused) {
  for (const std::vector<Point2>& line : ExtremeLines(s())) {
    Profile profile;
    ExpectProfileRight(s(), line, &profile);
  }
}

// 2^k times a line crosses 2^k times the unscaled line's crossings, the
// same triangles (by their corners' ids), with the same values.
TEST_P(ScaledTest, ProfilesScaleWithTheDataset) {
  const Served& unit = ScaledServed(0);
  const test::TriangleIndex unit_index(*unit.t), index(*s().t);
  const auto corners = [](const test::TriangleIndex& in, int64_t id) {
    if (id < 0) return std::set<int64_t>();
    return std::set<int64_t>(in.ids(id).begin(), in.ids(id).end());
  };
  // Integers, so that they scale exactly (to denormals too), and lines no
  // longer than the largest double at k = 971.
  constexpr double kCorner = 0x1p53 - 1;
  constexpr double kQuarter = 0x1p51;
  const std::vector<std::vector<Point2>> lines = {
      {{-3e6, -2.5e6}, {2.9e6, 3.1e6}},
      {{-kQuarter, 0}, {kQuarter, 1e6}, {0, kQuarter}},
      {{-2 * 0x1p20, -0x1p20}, {2 * 0x1p20, -0x1p20}},  // along grid edges
      {{kCorner, kCorner}, {kQuarter, 2 * kQuarter}},   // from a corner
  };
  for (const std::vector<Point2>& unit_line : lines) {
    std::vector<Point2> line;
    for (const Point2& p : unit_line) {
      line.push_back({std::ldexp(p.x, k()), std::ldexp(p.y, k())});
    }
    Profile want, got;
    ExpectProfileRight(unit, unit_line, &want);
    ExpectProfileRight(s(), line, &got);
    ASSERT_EQ(got.breakpoints.size(), want.breakpoints.size());
    // Unscaled, a coordinate keeps the unit one's 53 bits but below 2^-1022.
    const double slack = std::ldexp(4.0, -1074 - k());
    for (size_t i = 0; i < got.breakpoints.size(); ++i) {
      const ProfilePoint& g = got.breakpoints[i];
      const ProfilePoint& w = want.breakpoints[i];
      EXPECT_EQ(g.kind, w.kind) << i;
      EXPECT_EQ(g.segment, w.segment) << i;
      EXPECT_EQ(corners(index, g.triangle_id),
                corners(unit_index, w.triangle_id))
          << i;
      for (const auto& [a, b] :
           {std::pair{g.point.x, w.point.x}, std::pair{g.point.y, w.point.y},
            std::pair{g.distance, w.distance}}) {
        EXPECT_NEAR(std::ldexp(a, -k()), b, 1e-12 * std::abs(b) + slack) << i;
      }
      EXPECT_EQ(g.has_value, w.has_value) << i;
      if (g.has_value) {
        EXPECT_NEAR(g.value, w.value, 1e-9) << i;
      }
    }
  }
}

TEST_P(ScaledTest, RastersAgreeWithLocate) { ExpectRastersRight(s()); }

std::string ScaleName(const ::testing::TestParamInfo<int>& info) {
  return (info.param < 0 ? "TwoToMinus" : "TwoTo") +
         std::to_string(std::abs(info.param));
}

INSTANTIATE_TEST_SUITE_P(Scales, ScaledTest, ::testing::ValuesIn(kScales),
                         ScaleName);

// Points at every magnitude at once, with values anywhere in +-DBL_MAX.
class MixedTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { served_ = Serve(MixedDataset()).release(); }
  static void TearDownTestSuite() {
    delete served_;
    served_ = nullptr;
  }
  void SetUp() override { ASSERT_NE(served_, nullptr); }
  static const Served& s() { return *served_; }

 private:
  static Served* served_;
};

Served* MixedTest::served_ = nullptr;

TEST_F(MixedTest, LocatesAgreeWithCgal) {
  ExpectLocatesRight(s(), QueriesFor(s()));
}

// Natural neighbour over these needles mostly takes exact rationals: a
// share of the queries and lines keeps the test short.
TEST_F(MixedTest, InterpolatedValuesStayWithinTheValues) {
  ExpectInterpolationsRight(s(), EveryNth(QueriesFor(s()), 5), nullptr, 0);
}

TEST_F(MixedTest, ExtremeProfilesAreRightOrRefused) {
  const std::vector<std::vector<Point2>> lines = ExtremeLines(s());
  for (size_t i = 0; i < lines.size(); ++i) {
    Profile profile;
    ExpectProfileRight(s(), lines[i], &profile, /*natural=*/i < 6);
  }
}

TEST_F(MixedTest, RastersAgreeWithLocate) { ExpectRastersRight(s()); }

// The issue's request: a profile from (-1e160, -1e160) to (1e160, 1e160)
// over a dataset with values. Its crossings' points were NaN (the cross
// products overflowed), and their values went to GMP as NaN: SIGFPE.
TEST(ExtremeProfileTest, TheIssuesLineCrossesAtFinitePoints) {
  std::unique_ptr<Served> s = Serve(test::PlaneDataset(300, 30));
  ASSERT_NE(s, nullptr);
  Profile profile;
  ExpectProfileRight(*s, {{-1e160, -1e160}, {1e160, 1e160}}, &profile);
  EXPECT_GT(profile.crossings, 2u);
  for (const ProfilePoint& b : profile.breakpoints) {
    if (b.kind == ProfilePointKind::kLineVertex) continue;
    EXPECT_NEAR(b.point.x, b.point.y, 1e-12);  // on the diagonal
    ASSERT_TRUE(b.has_value);
    EXPECT_NEAR(b.value, test::Plane(b.point), 1e-9);
  }
}

// A line longer than the largest double: its length and distances cannot
// be represented, so it is refused, naming the point where it gets there.
TEST(ExtremeProfileTest, LineLongerThanADoubleIsRefused) {
  std::unique_ptr<Served> s = Serve(test::PlaneDataset(50, 31));
  ASSERT_NE(s, nullptr);
  Profile profile;
  const std::vector<Point2> line = {{0, 0}, {kMax, 0}, {-kMax, 0}};
  const Status status = s->engine().TraceProfile(line, {}, &profile);
  ASSERT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(status.message(),
            "profile: the line up to line point 2 is longer than the largest "
            "double, 1.7976931348623157e+308: distances along it cannot be "
            "represented; the line's length must stay within that");
  const std::vector<Point2> just = {{-kMax / 2, 0}, {kMax / 2, 0}};
  EXPECT_TRUE(s->engine().TraceProfile(just, {}, &profile).ok());
  EXPECT_EQ(profile.length, kMax);
}

// A raster whose cells are no doubles is refused naming the box, the cell
// count and the cell size; one cell fewer wide than the box is fine.
TEST(ExtremeRasterTest, CellsMustBeDoubles) {
  const Status wide = CheckRasterSpec(
      RasterSpec{.box = {-kMax, -1, kMax, 1}, .width = 1, .height = 1});
  ASSERT_EQ(wide.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(wide.message(),
            "the raster's cells are not representable: the box "
            "(-1.7976931348623157e+308, -1) - (1.7976931348623157e+308, 1) "
            "over 1 x 1 cells makes cells of inf x 2; a cell's width and "
            "height must be positive doubles, at most "
            "1.7976931348623157e+308");
  EXPECT_TRUE(
      CheckRasterSpec(
          RasterSpec{.box = {-kMax, -1, kMax, 1}, .width = 2, .height = 1})
          .ok());
  const Status tiny = CheckRasterSpec(
      RasterSpec{.box = {0, 0, L::denorm_min(), 1}, .width = 4, .height = 1});
  ASSERT_EQ(tiny.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(tiny.message().find("cells of 0 x 1"), std::string::npos)
      << tiny.message();
}

// Numbers at the ends of the doubles load as written: the largest double,
// the smallest denormal, -0; beyond the doubles they are refused.
TEST(ExtremeLoadTest, TextKeepsEveryFiniteDouble) {
  const StatusOr<Dataset> parsed = ParseXyzText(
      "1.7976931348623157e308,-1.7976931348623157e308,"
      "1.7976931348623157e308\n"
      "-1.7976931348623157e308,4.9e-324,-4.9e-324\n"
      "2.2250738585072014e-308,-0,1e160\n"
      "1e300,1e300,-0\n",
      "extreme.csv");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const Dataset& ds = *parsed;
  ASSERT_EQ(ds.points.size(), 4u);
  EXPECT_EQ(ds.points[0].x, kMax);
  EXPECT_EQ(ds.points[1].y, L::denorm_min());
  EXPECT_EQ(ds.values[1], -L::denorm_min());
  EXPECT_EQ(ds.points[2].x, L::min());
  EXPECT_TRUE(std::signbit(ds.points[2].y));
  std::unique_ptr<Served> s = Serve(ds);
  ASSERT_NE(s, nullptr);
  ExpectLocatesRight(*s, QueriesFor(*s));
  ExpectInterpolationsRight(*s, EveryNth(QueriesFor(*s), 5), nullptr, 0);
  const Status beyond = ParseXyzText("1e309,0,0\n", "beyond.csv").status();
  EXPECT_EQ(beyond.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(beyond.message().find("beyond.csv:1: non-finite coordinate"),
            std::string::npos)
      << beyond.message();
}

// Breaklines that cross each other away from any vertex, at every scale
// up to +-DBL_MAX: CGAL inserts the crossing as a new vertex, at a finite
// point with a finite value between the lines' ends.
TEST(ExtremeConstraintsTest, CrossingBreaklinesAtEveryScale) {
  for (const int k : kScales) {
    Dataset ds = ScaledDataset(k);
    const auto at = [k](double x, double y) {
      constexpr double kCorner = 0x1p53 - 1;
      return Point2{std::ldexp(std::round(x * kCorner), k),
                    std::ldexp(std::round(y * kCorner), k)};
    };
    ds.constraints.breaklines.push_back(
        {{at(-1, -0.5), at(1, 0.7)}, {ds.values[0], kMax}});
    ds.constraints.breaklines.push_back(
        {{at(-1, 0.9), at(1, -0.3)}, {-kMax, ds.values[1]}});
    std::unique_ptr<Served> s = Serve(ds);
    ASSERT_NE(s, nullptr) << k;
    // The crossing takes the id after the lines' four ends, and its value
    // along the first line.
    const ServingMesh& mesh = s->t->mesh();
    const Polyline& first = ds.constraints.breaklines[0];
    int crossings = 0;
    for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
      if (mesh.PublicId(v) != int64_t(ds.points.size() + 4)) continue;
      ++crossings;
      const Point2& at = mesh.arrays().points[v];
      const Wide w = Distance(first.points[0], at) /
                     Distance(first.points[0], first.points[1]);
      const double want = Lerp(first.values[0], first.values[1], w);
      EXPECT_NEAR(mesh.arrays().values[v], want, 1e-9 * std::abs(want))
          << k << ": crossing at " << PointText(at);
    }
    EXPECT_EQ(crossings, 1) << k;
    ExpectLocatesRight(*s, QueriesFor(*s));
  }
}

// Breaklines whose crossing lies beyond the doubles (dataset_fuzzer found
// them): CGAL cannot compute the crossing point, and the build is refused
// naming why instead of aborting on CGAL's exception.
TEST(ExtremeConstraintsTest, CrossingsBeyondDoublesAreRefused) {
  Dataset ds;
  ds.points = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  StatusOr<DatasetConstraints> constraints = ParseWktConstraints(
      "LINESTRING (-1e300 -1e300, 1e300 1.7976931348623157e308)\n"
      "LINESTRING (-1.7976931348623157e308 1e300, 1e160 -1e160, "
      "1e300 -1e300)\n"
      "POLYGON ((-1e300 -1e300, 1e300 -1e300, 1e300 1e300, "
      "-1e300 1e300, -1e300 -1e300))\n",
      "crossing.wkt");
  ASSERT_TRUE(constraints.ok()) << constraints.status().ToString();
  ds.constraints = *std::move(constraints);
  const Status s = Triangulation::Build(ds).status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  EXPECT_NE(s.message().find("cannot be computed in doubles"),
            std::string::npos)
      << s.ToString();
}

}  // namespace
}  // namespace locator
