// An engine finds each query's face once, with its strategy, and computes
// each value once, by the interpolation asked for: for NEAREST and
// NATURAL_NEIGHBOR the strategy is asked for everything but the value, and
// the value is interpolated in the face it found.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "tests/core/engine_test_peer.h"

namespace locator {
namespace {

// Counts the faces the engine asks its strategy to find, and the details.
class CountingLocator final : public PointLocator {
 public:
  explicit CountingLocator(std::unique_ptr<PointLocator> inner)
      : inner_(std::move(inner)) {}

  void Locate(const Point2& q, LocateResult* result,
              Detail detail) const override {
    ++lookups;
    details.push_back(detail);
    inner_->Locate(q, result, detail);
  }
  void LocateMany(std::span<const Point2> queries, LocateResult* results,
                  Detail detail) const override {
    lookups += queries.size();
    details.push_back(detail);
    inner_->LocateMany(queries, results, detail);
  }
  std::string_view name() const override { return inner_->name(); }
  TuningSummary Summary() const override { return inner_->Summary(); }

  mutable size_t lookups = 0;
  mutable std::vector<Detail> details;

 private:
  const std::unique_ptr<PointLocator> inner_;
};

class FaceLookupTest : public ::testing::TestWithParam<Interpolation> {
 protected:
  void SetUp() override {
    Dataset dataset = GenerateUniform(2000, 11);
    for (const Point2& p : dataset.points) {
      dataset.values.push_back(std::sin(7 * p.x) + p.y * p.y);
    }
    values_ = dataset.values;
    StatusOr<std::unique_ptr<Engine>> engine =
        Engine::Create(dataset, EngineOptions());
    ASSERT_TRUE(engine.ok());
    StatusOr<std::unique_ptr<Engine>> reference =
        Engine::Create(dataset, EngineOptions());
    ASSERT_TRUE(reference.ok());
    reference_ = *std::move(reference);
    engine_ = *std::move(engine);
    EngineTestPeer::WrapStrategy(*engine_, [this](auto strategy) {
      auto counting = std::make_unique<CountingLocator>(std::move(strategy));
      counting_ = counting.get();
      return counting;
    });
  }

  // What the strategy is asked for when the value is interpolated `how`.
  static Detail ExpectedDetail(Interpolation how) {
    return how == Interpolation::kLinear ? Detail::kFull : Detail::kAllButValue;
  }

  std::vector<double> values_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<Engine> reference_;  // the same dataset, unwatched
  CountingLocator* counting_ = nullptr;
};

std::vector<Point2> Queries() {
  std::vector<Point2> queries;
  for (int i = 0; i < 50; ++i) {
    queries.push_back(Point2{(i % 10 + 0.37) / 10, (i / 10 + 0.61) / 5});
  }
  return queries;
}

TEST_P(FaceLookupTest, ALocateFindsItsFaceOnceAndComputesItsValueOnce) {
  const Interpolation how = GetParam();
  for (const Point2& q : Queries()) {
    counting_->lookups = 0;
    counting_->details.clear();
    LocateResult result;
    ASSERT_TRUE(engine_->Locate(q, &result, how).ok());
    EXPECT_EQ(counting_->lookups, 1u);
    ASSERT_EQ(counting_->details.size(), 1u);
    EXPECT_EQ(counting_->details[0], ExpectedDetail(how));
    LocateResult expected;
    ASSERT_TRUE(reference_->Locate(q, &expected, how).ok());
    ASSERT_TRUE(result.has_value);
    EXPECT_EQ(result.triangle_id, expected.triangle_id);
    EXPECT_EQ(result.value, expected.value);
    if (how == Interpolation::kNearest) {
      // The value of the located triangle's corner nearest to q.
      double best = std::numeric_limits<double>::infinity();
      double nearest = 0;
      for (int i = 0; i < 3; ++i) {
        const double d =
            std::hypot(result.vertices[i].x - q.x, result.vertices[i].y - q.y);
        if (d < best) {
          best = d;
          nearest = values_[result.vertex_ids[i]];
        }
      }
      EXPECT_EQ(result.value, nearest);
    }
  }
}

TEST_P(FaceLookupTest, ABatchFindsEachFaceOnce) {
  const Interpolation how = GetParam();
  const std::vector<Point2> queries = Queries();
  std::vector<LocateResult> results;
  ASSERT_TRUE(
      engine_->LocateBatch(queries, &results, nullptr, how, Detail::kFull)
          .ok());
  EXPECT_EQ(counting_->lookups, queries.size());
  for (Detail detail : counting_->details) {
    EXPECT_EQ(detail, ExpectedDetail(how));
  }
  for (size_t i = 0; i < queries.size(); ++i) {
    LocateResult expected;
    ASSERT_TRUE(reference_->Locate(queries[i], &expected, how).ok());
    EXPECT_EQ(results[i].value, expected.value) << i;
  }
  // Without values, nothing is interpolated at all.
  counting_->details.clear();
  ASSERT_TRUE(
      engine_->LocateBatch(queries, &results, nullptr, how, Detail::kLocation)
          .ok());
  for (Detail detail : counting_->details) {
    EXPECT_EQ(detail, Detail::kLocation);
  }
  EXPECT_FALSE(results[0].has_value);
}

INSTANTIATE_TEST_SUITE_P(
    Interpolations, FaceLookupTest,
    ::testing::Values(Interpolation::kLinear, Interpolation::kNearest,
                      Interpolation::kNaturalNeighbor),
    [](const ::testing::TestParamInfo<Interpolation>& info) {
      std::string name(InterpolationName(info.param));
      std::erase(name, '-');
      return name;
    });

}  // namespace
}  // namespace locator
