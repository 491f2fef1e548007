// Every strategy answers exactly what CGAL's locate() answers
// (Triangulation::ReferenceLocate), on every workload and on the hard
// points: vertices, edge midpoints, outside the hull and very far away.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "server/core/strategies/locator_factory.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using test::ReferenceAnswers;

constexpr size_t kQueriesPerWorkload = 10000;

// Small intervals, so the learning strategies finish their warm-up and
// re-tune many times inside every run.
TuningOptions FastLearning() {
  TuningOptions options;
  options.warmup_queries = 500;
  options.retune_every = 500;
  // A table small enough that inline builds (kTuneUnitsPerQuery starts per
  // query) end within retune_every queries, so every interval re-tunes.
  options.budget_fraction = 0.03;
  return options;
}

const std::map<std::string, std::function<Dataset()>>& Datasets() {
  static const auto* datasets =
      new std::map<std::string, std::function<Dataset()>>{
          {"uniform", [] { return GenerateUniform(20000, 1); }},
          {"grid", [] { return test::GridDataset(100); }},
          {"clusters", [] { return GenerateClusters(20000, 5, 2); }},
          {"values", [] { return test::PlaneDataset(10000, 3); }},
      };
  return *datasets;
}

// Queries with their reference answers.
struct Checked {
  std::vector<Point2> queries;
  std::vector<LocateResult> refs;
};

// A dataset's triangulation, built once per process and shared by the
// strategies; query sets are computed on first use.
struct Fixture {
  Dataset dataset;
  std::unique_ptr<Triangulation> t;
  std::unique_ptr<test::TriangleIndex> index;
  std::map<std::string, Checked> sets;

  const Checked& Set(const std::string& name,
                     const std::function<std::vector<Point2>()>& make) {
    auto it = sets.find(name);
    if (it == sets.end()) {
      Checked c;
      c.queries = make();
      c.refs = ReferenceAnswers(*t, c.queries);
      it = sets.emplace(name, std::move(c)).first;
    }
    return it->second;
  }
};

Fixture* GetFixture(const std::string& name) {
  static auto* fixtures = new std::map<std::string, std::unique_ptr<Fixture>>;
  auto& f = (*fixtures)[name];
  if (!f) {
    f = std::make_unique<Fixture>();
    f->dataset = Datasets().at(name)();
    f->t = test::BuildTriangulation(f->dataset);
    if (f->t) f->index = std::make_unique<test::TriangleIndex>(*f->t);
  }
  return f->t ? f.get() : nullptr;
}

// Squared distance from q to segment ab, in long double like the core.
long double SegmentDistance2(const Point2& a, const Point2& b,
                             const Point2& q) {
  const long double abx = (long double)b.x - a.x, aby = (long double)b.y - a.y;
  const long double aqx = (long double)q.x - a.x, aqy = (long double)q.y - a.y;
  long double s = (aqx * abx + aqy * aby) / (abx * abx + aby * aby);
  s = s < 0 ? 0 : (s > 1 ? 1 : s);
  const long double dx = aqx - s * abx, dy = aqy - s * aby;
  return dx * dx + dy * dy;
}

using Param = std::tuple<std::string, std::string>;  // strategy, dataset

class AgreementTest : public ::testing::TestWithParam<Param> {
 protected:
  void SetUp() override {
    fixture_ = GetFixture(std::get<1>(GetParam()));
    ASSERT_NE(fixture_, nullptr);
  }

  const Triangulation& t() const { return *fixture_->t; }
  const std::string& strategy() const { return std::get<0>(GetParam()); }
  bool learns() const {
    return strategy() == "self-tuning" || strategy() == "adaptive-paper";
  }

  // A fresh locator that has already tuned for (1-cluster) traffic, so the
  // hard points below also exercise its cold paths.
  std::unique_ptr<PointLocator> TunedLocator() const {
    auto locator = test::MakeLocator(strategy(), t(), FastLearning());
    if (locator) {
      LocateResult r;
      for (const Point2& q : WorkloadQueries(WorkloadKind::kOneCluster,
                                             t().bounding_box(), 2000, 77)) {
        locator->Locate(q, &r);
      }
    }
    return locator;
  }

  void ExpectAgreement(const Checked& set) const {
    auto locator = TunedLocator();
    ASSERT_NE(locator, nullptr);
    EXPECT_TRUE(
        test::AllAgree(*locator, t(), *fixture_->index, set.queries, set.refs));
  }

  Fixture* fixture_ = nullptr;
};

TEST_P(AgreementTest, EveryWorkload) {
  for (WorkloadKind kind : AllWorkloadKinds()) {
    SCOPED_TRACE(WorkloadName(kind));
    const Checked& set = fixture_->Set(std::string(WorkloadName(kind)), [&] {
      return WorkloadQueries(kind, t().bounding_box(), kQueriesPerWorkload,
                             1000 + int(kind));
    });
    const TuningOptions options = FastLearning();
    auto locator = test::MakeLocator(strategy(), t(), options);
    ASSERT_NE(locator, nullptr);
    EXPECT_TRUE(
        test::AllAgree(*locator, t(), *fixture_->index, set.queries, set.refs));
    const TuningSummary s = locator->Summary();
    if (strategy() == "self-tuning") {
      // A re-tune that comes due while a table is still being built waits
      // for it (at most one block of kColdCheckEvery queries per build).
      EXPECT_GE(s.retune_count, kQueriesPerWorkload / options.retune_every - 1);
    } else if (strategy() == "adaptive-paper") {
      EXPECT_EQ(s.snapshot_version, 1u) << "warm-up did not complete";
    }
  }
}

TEST_P(AgreementTest, EveryVertexExactly) {
  const Checked& set =
      fixture_->Set("vertices", [&] { return fixture_->dataset.points; });
  for (const LocateResult& ref : set.refs) {
    ASSERT_EQ(ref.type, LocationType::kVertex);
  }
  ExpectAgreement(set);
}

TEST_P(AgreementTest, OutsideTheHull) {
  const Checked& set = fixture_->Set("outside", [&] {
    std::vector<Point2> outside;
    for (const Point2& q : test::UniformQueries(
             t().bounding_box().Inflated(0.5), 2 * kQueriesPerWorkload, 5)) {
      if (t().ReferenceLocate(q).type == LocationType::kOutsideConvexHull) {
        outside.push_back(q);
      }
    }
    return outside;
  });
  ASSERT_GT(set.queries.size(), kQueriesPerWorkload);
  ExpectAgreement(set);
}

TEST_P(AgreementTest, OutsideAnswersNameTheNearestHullEdge) {
  std::vector<std::array<Point2, 2>> hull;
  const auto& dt = t().cgal();
  auto fc = dt.incident_faces(dt.infinite_vertex()), end = fc;
  do {
    const int k = fc->index(dt.infinite_vertex());
    hull.push_back({Triangulation::FromCgal(fc->vertex((k + 1) % 3)->point()),
                    Triangulation::FromCgal(fc->vertex((k + 2) % 3)->point())});
  } while (++fc != end);
  auto locator = TunedLocator();
  ASSERT_NE(locator, nullptr);
  int failures = 0;
  LocateResult r;
  for (const Point2& q :
       test::UniformQueries(t().bounding_box().Inflated(2), 3000, 6)) {
    locator->Locate(q, &r);
    if (r.type != LocationType::kOutsideConvexHull) continue;
    long double nearest = SegmentDistance2(hull[0][0], hull[0][1], q);
    for (const auto& e : hull) {
      nearest = std::min(nearest, SegmentDistance2(e[0], e[1], q));
    }
    Point2 a, b;
    ASSERT_TRUE(t().VertexPoint(r.hull_edge_ids[0], &a));
    ASSERT_TRUE(t().VertexPoint(r.hull_edge_ids[1], &b));
    const long double got = SegmentDistance2(a, b, q);
    if (got > nearest * (1 + 1e-12L) && ++failures <= 5) {
      ADD_FAILURE() << test::DescribeAnswer(q, r) << " is at distance^2 "
                    << double(got) << ", the nearest hull edge at "
                    << double(nearest);
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST_P(AgreementTest, VeryFarAway) {
  const Checked& set = fixture_->Set("far", [&] {
    std::vector<Point2> far;
    for (double big : {1e300, 1e308, DBL_MAX}) {
      for (double sx : {-1.0, 0.0, 1.0}) {
        for (double sy : {-1.0, 0.0, 1.0}) {
          if (sx != 0 || sy != 0) far.push_back({sx * big, sy * big});
        }
      }
    }
    const BoundingBox& box = t().bounding_box();
    // Far out on the lines through the box's sides: collinear with the hull
    // edges of the grid.
    for (double big : {1e3, 1e308}) {
      far.push_back({big, box.min_y});
      far.push_back({-big, box.max_y});
      far.push_back({box.min_x, -big});
      far.push_back({box.max_x, big});
    }
    far.push_back({1e-300, -1e308});
    far.push_back({-1e308, 0.5});
    return far;
  });
  for (const LocateResult& ref : set.refs) {
    ASSERT_EQ(ref.type, LocationType::kOutsideConvexHull);
  }
  ExpectAgreement(set);
}

// A test name from strategy names: gtest allows no '-'.
std::string TestName(std::string name) {
  for (char& c : name) c = (c == '-') ? '_' : c;
  return name;
}

std::string ParamName(const ::testing::TestParamInfo<Param>& info) {
  return TestName(std::get<0>(info.param) + "_" + std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(
    AllStrategies, AgreementTest,
    ::testing::Combine(::testing::ValuesIn(StrategyNames()),
                       ::testing::Values("uniform", "grid", "clusters",
                                         "values")),
    ParamName);

// A strategy that is wrong in a controlled way, to show the checks can fail.
class BrokenLocator : public PointLocator {
 public:
  enum class Fault { kShifted, kBarycentric, kWrongType };
  BrokenLocator(const PointLocator& inner, Fault fault)
      : inner_(inner), fault_(fault) {}

  void Locate(const Point2& q, LocateResult* r,
              Detail detail = Detail::kFull) const override {
    if (fault_ == Fault::kShifted) {
      inner_.Locate({q.x + 0.01, q.y}, r, detail);
      return;
    }
    inner_.Locate(q, r, detail);
    if (fault_ == Fault::kBarycentric) r->barycentric[0] += 1e-6;
    if (fault_ == Fault::kWrongType && r->type == LocationType::kFace) {
      r->type = LocationType::kEdge;
      r->feature_index = 0;
    }
  }
  std::string_view name() const override { return "broken"; }
  TuningSummary Summary() const override { return {}; }

 private:
  const PointLocator& inner_;
  const Fault fault_;
};

TEST(AgreementCheckTest, CatchesWrongAnswers) {
  Fixture* f = GetFixture("uniform");
  ASSERT_NE(f, nullptr);
  const auto queries = test::UniformQueries(f->t->bounding_box(), 1000, 3);
  const auto refs = ReferenceAnswers(*f->t, queries);
  auto walk = test::MakeLocator("walk", *f->t);
  ASSERT_NE(walk, nullptr);
  EXPECT_TRUE(test::AllAgree(*walk, *f->t, *f->index, queries, refs));
  for (auto fault :
       {BrokenLocator::Fault::kShifted, BrokenLocator::Fault::kBarycentric,
        BrokenLocator::Fault::kWrongType}) {
    const BrokenLocator broken(*walk, fault);
    EXPECT_FALSE(test::AllAgree(broken, *f->t, *f->index, queries, refs))
        << "fault " << int(fault);
  }
}

class GridEdgeTest : public ::testing::TestWithParam<std::string> {};

// On the integer grid every edge midpoint (x + 0.5 or y + 0.5) is exact, so
// it lies exactly on its edge: axis-aligned and diagonal edges alike.
TEST_P(GridEdgeTest, EveryEdgeMidpointIsAnEdge) {
  Fixture* f = GetFixture("grid");
  ASSERT_NE(f, nullptr);
  int diagonals = 0;
  const Checked& set = f->Set("midpoints", [&] {
    std::vector<Point2> mids;
    const auto& dt = f->t->cgal();
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const Point2 a = Triangulation::FromCgal(
          e->first->vertex((e->second + 1) % 3)->point());
      const Point2 b = Triangulation::FromCgal(
          e->first->vertex((e->second + 2) % 3)->point());
      mids.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
    }
    return mids;
  });
  for (const Point2& m : set.queries) {
    diagonals += (m.x != std::floor(m.x)) && (m.y != std::floor(m.y));
  }
  EXPECT_GT(diagonals, 1000);
  for (const LocateResult& ref : set.refs) {
    ASSERT_EQ(ref.type, LocationType::kEdge);
  }
  auto locator = test::MakeLocator(GetParam(), *f->t, FastLearning());
  ASSERT_NE(locator, nullptr);
  EXPECT_TRUE(
      test::AllAgree(*locator, *f->t, *f->index, set.queries, set.refs));
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, GridEdgeTest,
                         ::testing::ValuesIn(StrategyNames()),
                         [](const auto& info) { return TestName(info.param); });

}  // namespace
}  // namespace locator
