// Tuning that survives restarts: an engine restored from its state dir
// makes the same start choices (the same walk costs) as the one that saved
// it; unusable state files are ignored with a reason; saves are atomic and
// happen on the tuner thread.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "common/workload.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/core/dataset/file_io.h"
#include "tests/core/scratch_dir.h"
#include "tests/testing/wait.h"

namespace locator {
namespace {

using test::ScratchDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr size_t kPoints = 50000;
constexpr uint64_t kRetuneEvery = 1000;

// A small budget, so that a table tuned for the hot spot serves it clearly
// better than the untuned one.
EngineOptions Options(const std::string& state_dir) {
  EngineOptions options;
  options.tuning.budget_bytes = 32 * 1024;
  options.tuning.retune_every = kRetuneEvery;
  options.tuning.state_dir = state_dir;
  return options;
}

std::unique_ptr<Engine> NewEngine(const EngineOptions& options,
                                  uint64_t seed = 42) {
  StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(GenerateUniform(kPoints, seed), options);
  EXPECT_TRUE(engine.ok()) << engine.status().ToString();
  return engine.ok() ? *std::move(engine) : nullptr;
}

std::vector<Point2> Clustered(const Engine& engine, size_t n, uint64_t seed) {
  return WorkloadQueries(WorkloadKind::kOneCluster,
                         engine.dataset_info().bounding_box, n, seed);
}

void Feed(const Engine& engine, std::span<const Point2> queries) {
  LocateResult result;
  for (const Point2& q : queries) ASSERT_TRUE(engine.Locate(q, &result).ok());
}

// The cost of every query, located on a thread of its own: the walk's
// random edge order is per thread and starts the same on every new thread,
// so equal start choices give equal costs.
std::vector<uint32_t> CostsOnFreshThread(const Engine& engine,
                                         std::span<const Point2> queries) {
  std::vector<uint32_t> costs;
  std::thread([&] {
    LocateResult result;
    for (const Point2& q : queries) {
      EXPECT_TRUE(engine.Locate(q, &result).ok());
      costs.push_back(result.cost.total());
    }
  }).join();
  return costs;
}

double Mean(const std::vector<uint32_t>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

// An engine that learned the 1-cluster hot spot and saved it.
std::unique_ptr<Engine> TrainedAndSaved(const std::string& state_dir) {
  std::unique_ptr<Engine> engine = NewEngine(Options(state_dir));
  Feed(*engine, Clustered(*engine, 6 * kRetuneEvery, 1));
  engine->Retune();
  const Status saved = engine->SaveTuningState();
  EXPECT_TRUE(saved.ok()) << saved.ToString();
  return engine;
}

TEST(TuningPersistenceTest, ARestoredEngineStartsWhereTheSavedOneLeftOff) {
  ScratchDir dir;
  const std::unique_ptr<Engine> saved = TrainedAndSaved(dir.path());
  const TuningSummary before = saved->Stats().tuning;
  EXPECT_EQ(before.persistence.saves, 1u);
  EXPECT_FALSE(before.persistence.restored_from_state);
  ASSERT_THAT(dir.Entries(),
              ElementsAre(std::filesystem::path(before.persistence.state_path)
                              .filename()
                              .string()));

  const std::unique_ptr<Engine> restored = NewEngine(Options(dir.path()));
  const std::unique_ptr<Engine> fresh = NewEngine(Options(""));
  const TuningSummary after = restored->Stats().tuning;
  EXPECT_TRUE(after.persistence.restored_from_state);
  EXPECT_EQ(after.persistence.load_error, "");
  EXPECT_EQ(after.persistence.state_path, before.persistence.state_path);
  EXPECT_EQ(after.snapshot_version, before.snapshot_version);
  EXPECT_EQ(after.retune_count, before.retune_count);
  EXPECT_EQ(after.histogram, before.histogram);
  EXPECT_EQ(after.hot_regions.size(), before.hot_regions.size());
  EXPECT_EQ(after.start_point_count, before.start_point_count);
  EXPECT_EQ(after.memory_bytes, before.memory_bytes);
  ASSERT_EQ(after.start_points.size(), before.start_points.size());
  for (size_t i = 0; i < after.start_points.size(); ++i) {
    EXPECT_EQ(after.start_points[i].x, before.start_points[i].x);
    EXPECT_EQ(after.start_points[i].y, before.start_points[i].y);
  }

  // The first queries after the "restart" cost what they cost before it,
  // query by query, and clearly less than on an untrained engine.
  const std::vector<Point2> queries = Clustered(*saved, 500, 2);
  const std::vector<uint32_t> saved_costs = CostsOnFreshThread(*saved, queries);
  const std::vector<uint32_t> restored_costs =
      CostsOnFreshThread(*restored, queries);
  const std::vector<uint32_t> fresh_costs = CostsOnFreshThread(*fresh, queries);
  EXPECT_EQ(restored_costs, saved_costs);
  EXPECT_LT(Mean(restored_costs), 0.7 * Mean(fresh_costs))
      << Mean(restored_costs) << " restored vs " << Mean(fresh_costs)
      << " fresh";
}

TEST(TuningPersistenceTest, NothingIsWrittenWhenNothingWasLearned) {
  ScratchDir dir;
  const std::unique_ptr<Engine> engine = NewEngine(Options(dir.path()));
  EXPECT_TRUE(engine->SaveTuningState().ok());
  EXPECT_THAT(dir.Entries(), ::testing::IsEmpty());
  const std::unique_ptr<Engine> trained = TrainedAndSaved(dir.path());
  // A second save of the same snapshot writes nothing new.
  EXPECT_TRUE(trained->SaveTuningState().ok());
  EXPECT_EQ(trained->Stats().tuning.persistence.saves, 1u);
}

TEST(TuningPersistenceTest, UnusableFilesAreIgnoredWithTheReason) {
  ScratchDir dir;
  const std::string path =
      TrainedAndSaved(dir.path())->Stats().tuning.persistence.state_path;
  std::string good;
  ASSERT_TRUE(ReadWholeFile(path, "state", &good).ok());
  std::string flipped = good;
  flipped[good.size() / 2] ^= 1;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good.substr(0, good.size() / 2), "truncated"},
      {flipped, "checksum mismatch"},
      {"", "truncated tuning state: 0 bytes"},
  };
  for (const auto& [bytes, reason] : cases) {
    ASSERT_TRUE(WriteFileAtomically(path, bytes).ok());
    const std::unique_ptr<Engine> engine = NewEngine(Options(dir.path()));
    const PersistenceSummary p = engine->Stats().tuning.persistence;
    EXPECT_FALSE(p.restored_from_state) << reason;
    EXPECT_THAT(p.load_error, HasSubstr(reason));
    // It serves, untuned, and its first save replaces the bad file.
    Feed(*engine, Clustered(*engine, 2 * kRetuneEvery, 3));
    ASSERT_TRUE(engine->SaveTuningState().ok());
    EXPECT_TRUE(NewEngine(Options(dir.path()))
                    ->Stats()
                    .tuning.persistence.restored_from_state)
        << reason;
  }
}

TEST(TuningPersistenceTest, AnotherDatasetsStateIsForeign) {
  ScratchDir dir;
  const std::string saved_path =
      TrainedAndSaved(dir.path())->Stats().tuning.persistence.state_path;
  // Another dataset has a file name of its own in the same directory ...
  const std::unique_ptr<Engine> other = NewEngine(Options(dir.path()), 43);
  const std::string other_path = other->Stats().tuning.persistence.state_path;
  EXPECT_NE(other_path, saved_path);
  EXPECT_FALSE(other->Stats().tuning.persistence.restored_from_state);
  EXPECT_EQ(other->Stats().tuning.persistence.load_error, "");
  // ... and a state copied there from the first is recognised as foreign.
  std::filesystem::copy_file(saved_path, other_path);
  const PersistenceSummary p =
      NewEngine(Options(dir.path()), 43)->Stats().tuning.persistence;
  EXPECT_FALSE(p.restored_from_state);
  EXPECT_THAT(p.load_error, HasSubstr("saved for another dataset"));
}

TEST(TuningPersistenceTest, TheTunerThreadSavesAfterARetune) {
  ScratchDir dir;
  EngineOptions options = Options(dir.path());
  options.tuning.background = true;
  const std::unique_ptr<Engine> engine = NewEngine(options);
  Feed(*engine, Clustered(*engine, 3 * kRetuneEvery, 4));
  EXPECT_TRUE(test::WaitUntil(
      [&] { return engine->Stats().tuning.persistence.saves > 0; }));
  const PersistenceSummary p = engine->Stats().tuning.persistence;
  EXPECT_GE(p.saves, 1u);
  EXPECT_EQ(p.save_error, "");
  EXPECT_TRUE(std::filesystem::exists(p.state_path));
}

// Readers, the tuner thread's saves, explicit saves and stats all at once
// (run under ThreadSanitizer with ctest -L concurrency).
TEST(TuningPersistenceTest, SavesWhileManyThreadsLocate) {
  ScratchDir dir;
  EngineOptions options = Options(dir.path());
  options.tuning.background = true;
  const std::unique_ptr<Engine> engine = NewEngine(options);
  std::vector<std::thread> readers;
  for (uint64_t seed = 10; seed < 14; ++seed) {
    readers.emplace_back([&engine, seed] {
      Feed(*engine, Clustered(*engine, 5 * kRetuneEvery, seed));
    });
  }
  for (int k = 0; k < 20; ++k) {
    EXPECT_TRUE(engine->SaveTuningState().ok());
    EXPECT_EQ(engine->Stats().tuning.persistence.save_error, "");
  }
  for (std::thread& reader : readers) reader.join();
  // The tuner thread may not have re-tuned yet on a loaded machine, and the
  // untuned plan is never saved: re-tune now so there is something to keep.
  engine->Retune();
  EXPECT_TRUE(engine->SaveTuningState().ok());
  EXPECT_GE(engine->Stats().tuning.persistence.saves, 1u);
  EXPECT_TRUE(NewEngine(Options(dir.path()))
                  ->Stats()
                  .tuning.persistence.restored_from_state);
}

TEST(TuningPersistenceTest, AFailedSaveIsReported) {
  ScratchDir dir;
  const std::string gone = dir.path() + "/gone";
  std::filesystem::create_directory(gone);
  const std::unique_ptr<Engine> engine = NewEngine(Options(gone));
  std::filesystem::remove(gone);
  Feed(*engine, Clustered(*engine, 2 * kRetuneEvery, 5));
  const Status s = engine->SaveTuningState();
  EXPECT_EQ(s.code(), Status::Code::kIOError);
  const PersistenceSummary p = engine->Stats().tuning.persistence;
  EXPECT_EQ(p.saves, 0u);
  EXPECT_THAT(p.save_error, HasSubstr("cannot create"));
}

TEST(FileIoTest, AtomicWritesLeaveNoTemporaryFiles) {
  ScratchDir dir;
  const std::string path = dir.path() + "/file";
  ASSERT_TRUE(WriteFileAtomically(path, "first").ok());
  ASSERT_TRUE(WriteFileAtomically(path, "second, longer").ok());
  EXPECT_THAT(dir.Entries(), ElementsAre("file"));
  std::string contents;
  ASSERT_TRUE(ReadWholeFile(path, "file", &contents).ok());
  EXPECT_EQ(contents, "second, longer");

  // A rename that fails (the target is a directory) removes its temporary.
  const std::string blocked = dir.path() + "/blocked";
  std::filesystem::create_directory(blocked + "/");
  std::ofstream(blocked + "/keep") << "x";
  const Status s = WriteFileAtomically(blocked, "data");
  EXPECT_EQ(s.code(), Status::Code::kIOError);
  EXPECT_THAT(s.message(), HasSubstr("cannot rename"));
  EXPECT_THAT(dir.Entries(), ElementsAre("blocked", "file"));
}

TEST(FileIoTest, ReadWholeFileNamesWhatIsMissing) {
  ScratchDir dir;
  std::string contents;
  const Status s =
      ReadWholeFile(dir.path() + "/none", "tuning state", &contents);
  EXPECT_EQ(s.code(), Status::Code::kNotFound);
  EXPECT_THAT(s.message(), HasSubstr("cannot open tuning state '"));
  std::ofstream(dir.path() + "/big") << std::string(100, 'x');
  EXPECT_EQ(ReadWholeFile(dir.path() + "/big", "x", &contents, 99).code(),
            Status::Code::kResourceExhausted);
}

}  // namespace
}  // namespace locator
