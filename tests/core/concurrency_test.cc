// Many threads locating at once while the strategy re-tunes underneath
// them. Every answer is checked against a reference computed before the
// threads start. Run under ThreadSanitizer too (ctest label "concurrency").

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <latch>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "locator/engine.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

constexpr int kThreads = 4;
constexpr size_t kPerThread = 30000;
constexpr uint64_t kDatasetSeed = 21;
constexpr size_t kPoints = 20000;

// Thread i's traffic: the first kind for half its queries, then the second.
constexpr std::pair<WorkloadKind, WorkloadKind> kTraffic[kThreads] = {
    {WorkloadKind::kOneCluster, WorkloadKind::kDrift},
    {WorkloadKind::kThreeCluster, WorkloadKind::kUniform},
    {WorkloadKind::kDrift, WorkloadKind::kXCluster},
    {WorkloadKind::kDCluster, WorkloadKind::kOneCluster},
};

struct Stream {
  std::vector<Point2> queries;
  std::vector<LocateResult> refs;
};

// Tallies shared by the query threads.
struct Tally {
  std::atomic<uint64_t> located{0};
  std::atomic<uint64_t> wrong{0};
  // first_wrong[i] is written only by thread i, read after join.
  std::vector<std::string> first_wrong = std::vector<std::string>(kThreads);

  void Check(int thread, const Triangulation& t,
             const test::TriangleIndex& index, const Point2& q,
             const LocateResult& got, const LocateResult& ref) {
    located.fetch_add(1, std::memory_order_relaxed);
    std::string problem;
    if (!t.Agrees(q, got, ref)) {
      problem = "got " + test::DescribeAnswer(q, got) + ", reference " +
                test::DescribeAnswer(q, ref);
    } else if (auto ok = test::AnswerIsConsistent(t, index, q, got); !ok) {
      problem = ok.message();
    }
    if (problem.empty()) return;
    wrong.fetch_add(1, std::memory_order_relaxed);
    if (first_wrong[thread].empty()) first_wrong[thread] = problem;
  }

  void ExpectAllRight(uint64_t expected) const {
    EXPECT_EQ(located.load(), expected);
    EXPECT_EQ(wrong.load(), 0u);
    for (int i = 0; i < kThreads; ++i) {
      EXPECT_EQ(first_wrong[i], "") << "thread " << i;
    }
  }
};

class ConcurrencyTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    t_ = test::BuildTriangulation(GenerateUniform(kPoints, kDatasetSeed))
             .release();
    if (!t_) return;
    index_ = new test::TriangleIndex(*t_);
    streams_ = new std::vector<Stream>(kThreads);
    const BoundingBox& box = t_->bounding_box();
    for (int i = 0; i < kThreads; ++i) {
      Stream& s = (*streams_)[i];
      for (WorkloadKind kind : {kTraffic[i].first, kTraffic[i].second}) {
        const auto half =
            WorkloadQueries(kind, box, kPerThread / 2, 100 + i * 7 + int(kind));
        s.queries.insert(s.queries.end(), half.begin(), half.end());
      }
      s.refs = test::ReferenceAnswers(*t_, s.queries);
    }
  }
  static void TearDownTestSuite() {
    delete streams_;
    delete index_;
    delete t_;
  }
  void SetUp() override { ASSERT_NE(t_, nullptr); }

  // Runs body(i) on thread i, i < kThreads, all released at once.
  template <typename Body>
  static void RunThreads(Body body) {
    std::latch start(kThreads);
    std::vector<std::thread> threads;
    for (int i = 0; i < kThreads; ++i) {
      threads.emplace_back([&, i] {
        start.arrive_and_wait();
        body(i);
      });
    }
    for (std::thread& t : threads) t.join();
  }

  // Thread i locates stream i with `locator`, checking every answer; it
  // passes over its stream again while `again()` says so (checked between
  // passes). Returns the number of passes each thread made.
  static uint64_t RunLocator(const PointLocator& locator, Tally* tally,
                             const std::function<bool()>& again = nullptr) {
    std::atomic<uint64_t> passes{0};
    RunThreads([&](int i) {
      const Stream& s = (*streams_)[i];
      LocateResult r;
      do {
        for (size_t k = 0; k < s.queries.size(); ++k) {
          locator.Locate(s.queries[k], &r);
          tally->Check(i, *t_, *index_, s.queries[k], r, s.refs[k]);
        }
        passes.fetch_add(1, std::memory_order_relaxed);
      } while (again && again());
    });
    return passes.load();
  }

  static Triangulation* t_;
  static test::TriangleIndex* index_;
  static std::vector<Stream>* streams_;
};

Triangulation* ConcurrencyTest::t_ = nullptr;
test::TriangleIndex* ConcurrencyTest::index_ = nullptr;
std::vector<Stream>* ConcurrencyTest::streams_ = nullptr;

TEST_F(ConcurrencyTest, SelfTuningWithBackgroundRetunes) {
  TuningOptions options;
  options.background = true;
  options.retune_every = 1000;
  auto locator = test::MakeLocator("self-tuning", *t_, options);
  ASSERT_NE(locator, nullptr);
  Tally tally;
  // The tuner thread runs when the scheduler lets it: keep locating until it
  // has re-tuned 3 times under this load (bounded, for a starved machine).
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const uint64_t passes = RunLocator(*locator, &tally, [&] {
    return locator->Summary().retune_count < 3 &&
           std::chrono::steady_clock::now() < deadline;
  });
  tally.ExpectAllRight(passes * kPerThread);
  EXPECT_GE(locator->Summary().retune_count, 3u);
  EXPECT_GE(locator->Summary().snapshot_version, 4u);
}

TEST_F(ConcurrencyTest, SelfTuningWithInlineRetunes) {
  TuningOptions options;
  options.background = false;
  options.retune_every = 1000;
  auto locator = test::MakeLocator("self-tuning", *t_, options);
  ASSERT_NE(locator, nullptr);
  Tally tally;
  RunLocator(*locator, &tally);
  tally.ExpectAllRight(kThreads * kPerThread);
  const TuningSummary s = locator->Summary();
  EXPECT_GE(s.retune_count, 3u);
  EXPECT_EQ(s.snapshot_version, s.retune_count + 1);
}

TEST_F(ConcurrencyTest, AdaptivePaperWarmUpUnderConcurrency) {
  TuningOptions options;
  options.warmup_queries = 1000;
  auto locator = test::MakeLocator("adaptive-paper", *t_, options);
  ASSERT_NE(locator, nullptr);
  Tally tally;
  RunLocator(*locator, &tally);
  tally.ExpectAllRight(kThreads * kPerThread);
  const TuningSummary s = locator->Summary();
  EXPECT_EQ(s.snapshot_version, 1u) << "the warm-up must end exactly once";
  EXPECT_FALSE(s.hot_regions.empty());
}

TEST_F(ConcurrencyTest, EngineLocateBatchAndStatsConcurrently) {
  EngineOptions options;
  options.tuning.background = true;
  options.tuning.retune_every = 1000;
  StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(GenerateUniform(kPoints, kDatasetSeed), options);
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<Engine> engine = *std::move(created);
  std::atomic<uint64_t> errors{0};
  std::atomic<bool> done{false};
  std::atomic<uint64_t> stats_calls{0};
  std::atomic<uint64_t> stats_regressions{0};
  // Polls Stats() (and re-tunes now and then) while the others locate.
  std::thread observer([&] {
    uint64_t last = 0;
    while (!done.load()) {
      const EngineStats s = engine->Stats();
      if (s.queries < last || (s.queries > 0 && !(s.mean_cost_lifetime > 0))) {
        stats_regressions.fetch_add(1);
      }
      last = s.queries;
      if (stats_calls.fetch_add(1) % 50 == 0) engine->Retune();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  // Threads 0 and 1 use Locate(); 2 and 3 LocateBatch() in slices.
  constexpr size_t kSlice = 1000;
  static_assert(kPerThread % kSlice == 0);
  Tally tally;
  RunThreads([&](int i) {
    const Stream& s = (*streams_)[i];
    std::vector<LocateResult> results(kSlice);
    for (size_t b = 0; b < s.queries.size(); b += kSlice) {
      const std::span<const Point2> slice(s.queries.data() + b, kSlice);
      if (i < 2) {
        for (size_t k = 0; k < kSlice; ++k) {
          if (!engine->Locate(slice[k], &results[k]).ok()) errors.fetch_add(1);
        }
      } else if (!engine->LocateBatch(slice, &results).ok()) {
        errors.fetch_add(1);
      }
      for (size_t k = 0; k < kSlice; ++k) {
        tally.Check(i, *t_, *index_, slice[k], results[k], s.refs[b + k]);
      }
    }
  });
  done.store(true);
  observer.join();
  tally.ExpectAllRight(kThreads * kPerThread);
  EXPECT_EQ(errors.load(), 0u);
  EXPECT_GT(stats_calls.load(), 0u);
  EXPECT_EQ(stats_regressions.load(), 0u);
  const EngineStats stats = engine->Stats();
  EXPECT_EQ(stats.queries, kThreads * kPerThread);
  EXPECT_GE(stats.tuning.retune_count, 3u);
}

}  // namespace
}  // namespace locator
