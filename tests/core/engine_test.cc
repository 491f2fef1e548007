#include "locator/engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "server/core/cgal/triangulation.h"
#include "server/core/strategies/locator_factory.h"
#include "server/core/walk_cost_histogram.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// 3000 points on the plane z = 2x + 3y + 1, plus 5 repeats of earlier ones.
Dataset TestDataset() {
  Dataset ds = test::PlaneDataset(3000, 4);
  for (size_t i = 0; i < 5; ++i) {
    ds.points.push_back(ds.points[i * 10]);
    ds.values.push_back(ds.values[i * 10]);
  }
  ds.source = "engine-test";
  return ds;
}

StatusOr<std::unique_ptr<Engine>> CreateEngine(Dataset ds,
                                               const std::string& strategy) {
  EngineOptions options;
  options.strategy = strategy;
  return Engine::Create(std::move(ds), options);
}

class EngineTest : public ::testing::Test {
 protected:
  void SetUp() override {
    Dataset dataset = TestDataset();
    const auto before_create = std::chrono::steady_clock::now();
    StatusOr<std::unique_ptr<Engine>> engine =
        CreateEngine(std::move(dataset), "self-tuning");
    create_seconds_ = std::chrono::duration<double>(
                          std::chrono::steady_clock::now() - before_create)
                          .count();
    ASSERT_TRUE(engine.ok()) << engine.status().ToString();
    engine_ = *std::move(engine);
    t_ = test::BuildTriangulation(TestDataset());
    ASSERT_NE(t_, nullptr);
  }

  // Queries of every kind: inside, on vertices, outside the hull.
  std::vector<Point2> MixedQueries(size_t n) const {
    std::vector<Point2> q =
        test::UniformQueries(t_->bounding_box().Inflated(0.2), n, /*seed=*/8);
    const Dataset ds = TestDataset();
    for (size_t i = 0; i < n; i += 10) q[i] = ds.points[i % 3000];
    return q;
  }

  std::unique_ptr<Engine> engine_;
  // How long creating engine_ took, seen from outside.
  double create_seconds_ = 0;
  // The same triangulation the engine built, to check its answers.
  std::unique_ptr<Triangulation> t_;
};

TEST(EngineCreateTest, UnknownStrategyListsTheValidNames) {
  const Status s = CreateEngine(GenerateUniform(100, 1), "fastest").status();
  ASSERT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  EXPECT_NE(s.message().find("fastest"), std::string::npos) << s.message();
  for (const std::string& name : StrategyNames()) {
    EXPECT_NE(s.message().find(name), std::string::npos) << s.message();
  }
}

TEST(EngineCreateTest, CollinearOrTooFewPointsFail) {
  const Status collinear =
      CreateEngine(test::PointsDataset({{0, 0}, {1, 1}, {2, 2}, {3, 3}}),
                   "walk")
          .status();
  ASSERT_EQ(collinear.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(collinear.message().find("collinear"), std::string::npos)
      << collinear.message();
  const Status few =
      CreateEngine(test::PointsDataset({{0, 0}, {1, 1}}), "walk").status();
  EXPECT_EQ(few.code(), Status::Code::kInvalidArgument);
}

TEST(EngineCreateTest, TuningOptionsOutOfRangeFail) {
  EngineOptions options;
  options.tuning.grid_size = 0;
  const Status s = Engine::Create(GenerateUniform(100, 1), options).status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
}

TEST(EngineCreateTest, EveryStrategyIsAvailable) {
  for (const std::string& name : StrategyNames()) {
    const StatusOr<std::unique_ptr<Engine>> created =
        CreateEngine(GenerateUniform(500, 2), name);
    ASSERT_TRUE(created.ok());
    const std::unique_ptr<Engine>& engine = *created;
    EXPECT_EQ(engine->Stats().strategy, name);
    LocateResult r;
    ASSERT_TRUE(engine->Locate({0.5, 0.5}, &r).ok());
    EXPECT_GE(r.triangle_id, 0);
  }
}

TEST_F(EngineTest, LocateRejectsNonFiniteCoordinates) {
  LocateResult r;
  for (const Point2& q : {Point2{kNaN, 0.5}, Point2{0.5, kNaN},
                          Point2{kInf, 0.5}, Point2{0.5, -kInf}}) {
    const Status s = engine_->Locate(q, &r);
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
    EXPECT_NE(s.message().find("non-finite"), std::string::npos);
  }
  // Both coordinates in shortest form, not 309 digits of the finite one.
  const Status s =
      engine_->Locate({kNaN, -std::numeric_limits<double>::max()}, &r);
  EXPECT_EQ(s.message(),
            "query point has a non-finite coordinate "
            "(nan, -1.7976931348623157e+308)");
  EXPECT_EQ(engine_->Stats().queries, 0u);
  EXPECT_TRUE(engine_->Locate({1e308, -1e308}, &r).ok());  // huge is fine
  EXPECT_EQ(r.type, LocationType::kOutsideConvexHull);
}

TEST_F(EngineTest, EmptyBatchIsOk) {
  std::vector<LocateResult> results(3);
  const Status s = engine_->LocateBatch({}, &results);
  EXPECT_TRUE(s.ok()) << s.ToString();
  EXPECT_TRUE(results.empty());
  EXPECT_EQ(engine_->Stats().queries, 0u);
}

TEST_F(EngineTest, NonFinitePointFailsTheWholeBatch) {
  std::vector<LocateResult> results;
  ASSERT_TRUE(engine_->LocateBatch(MixedQueries(10), &results).ok());
  const uint64_t before = engine_->Stats().queries;
  ASSERT_EQ(before, 10u);
  for (size_t bad : {size_t{0}, size_t{7}, size_t{299}}) {
    std::vector<Point2> queries = MixedQueries(300);
    queries[bad].y = bad == 7 ? kNaN : -kInf;
    if (bad == 7) queries[200].x = kNaN;  // only the first is named
    const Status s = engine_->LocateBatch(queries, &results);
    ASSERT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
    EXPECT_NE(s.message().find("point " + std::to_string(bad) + " "),
              std::string::npos)
        << s.message();
    EXPECT_EQ(engine_->Stats().queries, before) << "located before failing";
  }
}

TEST_F(EngineTest, CancelledBatchIsUnavailable) {
  const std::vector<Point2> queries = MixedQueries(5000);
  std::vector<LocateResult> results;
  int polls = 0;
  Status s = engine_->LocateBatch(queries, &results, [&polls] {
    return ++polls < 3;  // cancel at the third poll
  });
  EXPECT_EQ(s.code(), Status::Code::kUnavailable) << s.ToString();
  EXPECT_EQ(polls, 3);
  const uint64_t located = engine_->Stats().queries;
  EXPECT_GT(located, 0u);
  EXPECT_LT(located, queries.size());

  polls = 0;
  s = engine_->LocateBatch(queries, &results, [&polls] {
    ++polls;
    return false;
  });
  EXPECT_EQ(s.code(), Status::Code::kUnavailable);
  EXPECT_EQ(polls, 1);
  EXPECT_EQ(engine_->Stats().queries, located) << "located after cancel";

  polls = 0;
  s = engine_->LocateBatch(queries, &results, [&polls] {
    ++polls;
    return true;
  });
  EXPECT_TRUE(s.ok()) << s.ToString();
  EXPECT_GT(polls, 1);
  EXPECT_EQ(results.size(), queries.size());
}

TEST_F(EngineTest, BatchAnswersMatchUnaryLocateInInputOrder) {
  const std::vector<Point2> queries = MixedQueries(4000);
  std::vector<LocateResult> batch;
  ASSERT_TRUE(engine_->LocateBatch(queries, &batch).ok());
  ASSERT_EQ(batch.size(), queries.size());
  int faces = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    LocateResult unary;
    ASSERT_TRUE(engine_->Locate(queries[i], &unary).ok());
    ASSERT_EQ(batch[i].type, unary.type) << "query " << i;
    if (unary.type == LocationType::kFace) {
      ++faces;
      EXPECT_EQ(batch[i].triangle_id, unary.triangle_id) << "query " << i;
      EXPECT_EQ(batch[i].vertex_ids, unary.vertex_ids) << "query " << i;
      EXPECT_EQ(batch[i].value, unary.value) << "query " << i;
    }
    EXPECT_TRUE(t_->Agrees(queries[i], batch[i], unary)) << "query " << i;
    EXPECT_TRUE(
        t_->Agrees(queries[i], batch[i], t_->ReferenceLocate(queries[i])))
        << "query " << i;
  }
  EXPECT_GT(faces, 1500);
}

TEST_F(EngineTest, LocationOnlyBatchSkipsBarycentricsAndValues) {
  const std::vector<Point2> queries = MixedQueries(2000);
  std::vector<LocateResult> full, location;
  ASSERT_TRUE(engine_->LocateBatch(queries, &full).ok());
  ASSERT_TRUE(engine_
                  ->LocateBatch(queries, &location, nullptr,
                                Interpolation::kLinear, Detail::kLocation)
                  .ok());
  int with_value = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(location[i].type, full[i].type) << "query " << i;
    EXPECT_TRUE(t_->Agrees(queries[i], location[i], full[i])) << "query " << i;
    EXPECT_EQ(location[i].hull_edge_ids, full[i].hull_edge_ids);
    EXPECT_EQ(location[i].domain_edge_ids, full[i].domain_edge_ids);
    EXPECT_FALSE(location[i].has_value) << "query " << i;
    EXPECT_EQ(location[i].barycentric, (std::array<double, 3>{0, 0, 0}));
    with_value += full[i].has_value;
  }
  EXPECT_GT(with_value, 1000);
}

TEST_F(EngineTest, StatsCountQueriesAndCosts) {
  EngineStats s = engine_->Stats();
  EXPECT_EQ(s.queries, 0u);
  EXPECT_EQ(s.mean_cost_lifetime, 0);
  EXPECT_EQ(s.strategy, "self-tuning");
  EXPECT_EQ(s.tuning.snapshot_version, 1u);

  const std::vector<Point2> queries = MixedQueries(1500);
  std::vector<double> costs;
  LocateResult r;
  for (const Point2& q : queries) {
    ASSERT_TRUE(engine_->Locate(q, &r).ok());
    costs.push_back(r.cost.total());
    if (costs.size() == 500) {
      // Before the first window completes, recent is the lifetime mean.
      s = engine_->Stats();
      EXPECT_DOUBLE_EQ(s.mean_cost_recent, s.mean_cost_lifetime);
    }
  }
  s = engine_->Stats();
  EXPECT_EQ(s.queries, queries.size());
  const double total = std::accumulate(costs.begin(), costs.end(), 0.0);
  EXPECT_GT(s.mean_cost_lifetime, 0);
  EXPECT_DOUBLE_EQ(s.mean_cost_lifetime, total / queries.size());
  const double first_window =
      std::accumulate(costs.begin(), costs.begin() + Engine::kStatsWindow,
                      0.0) /
      Engine::kStatsWindow;
  EXPECT_DOUBLE_EQ(s.mean_cost_recent, first_window);
}

TEST_F(EngineTest, StatsCountWalkCostsOfUnaryAndBatchQueries) {
  const std::vector<Point2> queries = MixedQueries(700);
  std::vector<uint64_t> expected(WalkCostHistogram::kUpperBounds.size() + 1);
  uint64_t faces = 0;
  uint64_t cost = 0;
  const auto count = [&](const LocateResult& r) {
    const auto& bounds = WalkCostHistogram::kUpperBounds;
    ++expected[std::lower_bound(bounds.begin(), bounds.end(),
                                r.cost.faces_visited) -
               bounds.begin()];
    faces += r.cost.faces_visited;
    cost += r.cost.total();
  };
  LocateResult r;
  for (size_t i = 0; i < 200; ++i) {
    ASSERT_TRUE(engine_->Locate(queries[i], &r).ok());
    count(r);
  }
  std::vector<LocateResult> batch;
  ASSERT_TRUE(
      engine_->LocateBatch(std::span(queries).subspan(200), &batch).ok());
  for (const LocateResult& answer : batch) count(answer);

  const EngineStats s = engine_->Stats();
  EXPECT_EQ(s.walk_costs.counts, expected);
  EXPECT_EQ(s.walk_costs.faces_sum, faces);
  EXPECT_EQ(s.total_cost, cost);
  EXPECT_EQ(s.tuning.hot_queries + s.tuning.fallback_queries, 700u);
}

TEST_F(EngineTest, EdgeSampleIsBoundedAndLiesInTheBox) {
  const auto& sample = engine_->EdgeSample();
  EXPECT_LE(sample.size(), kEdgeSampleSize);
  EXPECT_GE(sample.size(), kEdgeSampleSize / 2);
  const BoundingBox& box = engine_->dataset_info().bounding_box;
  for (const auto& [a, b] : sample) {
    EXPECT_TRUE(box.Contains(a) && box.Contains(b));
  }
  // Computed once: the same vector every time.
  EXPECT_EQ(&engine_->EdgeSample(), &sample);
}

TEST_F(EngineTest, StatsDescribeTheDataset) {
  const DatasetInfo& info = engine_->Stats().dataset;
  EXPECT_EQ(info.source, "engine-test");
  EXPECT_EQ(info.input_points, 3005u);
  EXPECT_EQ(info.vertices, 3000u);
  EXPECT_EQ(info.duplicates_merged, 5u);
  EXPECT_EQ(info.triangles, t_->num_triangles());
  EXPECT_TRUE(info.has_values);
  // The mesh only: CGAL's triangulation is freed after the build.
  EXPECT_EQ(info.triangulation_bytes, t_->mesh().MemoryBytes());
  // Measured, and within the time Create() took.
  EXPECT_GT(info.build_seconds, 0);
  EXPECT_LE(info.build_seconds, create_seconds_);
  const BoundingBox& box = t_->bounding_box();
  EXPECT_EQ(info.bounding_box.min_x, box.min_x);
  EXPECT_EQ(info.bounding_box.min_y, box.min_y);
  EXPECT_EQ(info.bounding_box.max_x, box.max_x);
  EXPECT_EQ(info.bounding_box.max_y, box.max_y);
  EXPECT_GT(box.width(), 0.99);
  EXPECT_EQ(engine_->dataset_info().triangles, info.triangles);

  const StatusOr<std::unique_ptr<Engine>> plain =
      CreateEngine(GenerateUniform(100, 1), "walk");
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE((*plain)->Stats().dataset.has_values);
  EXPECT_EQ((*plain)->Stats().dataset.duplicates_merged, 0u);
}

TEST_F(EngineTest, ValuesAreInterpolated) {
  LocateResult r;
  ASSERT_TRUE(engine_->Locate({0.4, 0.7}, &r).ok());
  ASSERT_TRUE(r.has_value);
  EXPECT_NEAR(r.value, test::Plane({0.4, 0.7}), 1e-9);
}

}  // namespace
}  // namespace locator
