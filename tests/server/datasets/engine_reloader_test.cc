// EngineReloader: one build at a time on its own thread, publish before
// done, and "reload in progress" while a build runs. The builds here are
// held at a barrier, so every state is observed by construction.

#include "server/datasets/engine_reloader.h"

#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "locator/dataset_sources.h"

namespace locator {
namespace {

std::shared_ptr<Engine> SmallEngine(uint64_t seed) {
  StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(GenerateUniform(200, seed), EngineOptions());
  EXPECT_TRUE(engine.ok()) << engine.status().ToString();
  return engine.ok() ? *std::move(engine) : nullptr;
}

// A build that reports when the first build starts and waits for Release()
// before finishing (later builds run through once released).
class HeldBuild {
 public:
  EngineReloader::Build Build() {
    return [this](const std::string& dataset, BuiltDataset* built) {
      built_datasets_.push_back(dataset);
      if (built_datasets_.size() == 1) started_.set_value();
      released_.wait();
      if (dataset == "bad") return Status::InvalidArgument("bad dataset");
      built->engine = SmallEngine(built_datasets_.size());
      return Status::OK();
    };
  }
  void WaitUntilStarted() { started_.get_future().wait(); }
  void Release() { release_.set_value(); }
  // Only read once the build has ended.
  const std::vector<std::string>& built_datasets() const {
    return built_datasets_;
  }

 private:
  std::promise<void> started_;
  std::promise<void> release_;
  std::shared_future<void> released_ = release_.get_future().share();
  std::vector<std::string> built_datasets_;
};

// What a reload's `done` received, and what the reloader said at that time.
struct Outcome {
  Status status;
  std::shared_ptr<Engine> engine;
  uint64_t generation = 0;
  bool in_progress_during_done = true;
  std::thread::id thread;
};

TEST(EngineReloaderTest, BuildsOnItsThreadPublishesThenCallsDone) {
  HeldBuild held;
  std::vector<std::shared_ptr<Engine>> published;
  std::unique_ptr<EngineReloader> reloader;
  reloader =
      std::make_unique<EngineReloader>(held.Build(), [&](BuiltDataset built) {
        published.push_back(std::move(built.engine));
        return uint64_t{41 + published.size()};
      });
  std::promise<Outcome> outcome;
  ASSERT_TRUE(
      reloader
          ->Start("uniform:200:1",
                  [&](const Status& status, std::shared_ptr<Engine> engine,
                      uint64_t generation) {
                    outcome.set_value({status, std::move(engine), generation,
                                       reloader->in_progress(),
                                       std::this_thread::get_id()});
                  })
          .ok());
  held.WaitUntilStarted();
  EXPECT_TRUE(reloader->in_progress());
  held.Release();
  const Outcome done = outcome.get_future().get();
  EXPECT_TRUE(done.status.ok()) << done.status.ToString();
  ASSERT_EQ(published.size(), 1u);
  EXPECT_EQ(done.engine, published[0]);
  EXPECT_EQ(done.generation, 42u);
  EXPECT_FALSE(done.in_progress_during_done);
  EXPECT_NE(done.thread, std::this_thread::get_id());
  EXPECT_FALSE(reloader->in_progress());
  EXPECT_EQ(held.built_datasets(), std::vector<std::string>{"uniform:200:1"});
}

TEST(EngineReloaderTest, SecondStartWhileBuildingIsRefused) {
  HeldBuild held;
  std::atomic<int> publishes{0};
  EngineReloader reloader(held.Build(), [&](BuiltDataset) {
    return static_cast<uint64_t>(++publishes);
  });
  std::promise<uint64_t> first_generation;
  ASSERT_TRUE(reloader
                  .Start("first",
                         [&](const Status&, std::shared_ptr<Engine>,
                             uint64_t generation) {
                           first_generation.set_value(generation);
                         })
                  .ok());
  held.WaitUntilStarted();
  std::atomic<bool> refused_done_called{false};
  const Status refused =
      reloader.Start("second", [&](const Status&, std::shared_ptr<Engine>,
                                   uint64_t) { refused_done_called = true; });
  EXPECT_EQ(refused.code(), Status::Code::kFailedPrecondition);
  EXPECT_EQ(refused.message(), "reload in progress");
  held.Release();
  EXPECT_EQ(first_generation.get_future().get(), 1u);

  // Finished: the next reload starts at once, on a new build thread.
  std::promise<uint64_t> next_generation;
  ASSERT_TRUE(reloader
                  .Start("third",
                         [&](const Status&, std::shared_ptr<Engine>,
                             uint64_t generation) {
                           next_generation.set_value(generation);
                         })
                  .ok());
  EXPECT_EQ(next_generation.get_future().get(), 2u);
  EXPECT_FALSE(refused_done_called.load());
  EXPECT_EQ(held.built_datasets(),
            (std::vector<std::string>{"first", "third"}));
}

TEST(EngineReloaderTest, FailedBuildIsNotPublished) {
  HeldBuild held;
  std::atomic<int> publishes{0};
  EngineReloader reloader(held.Build(), [&](BuiltDataset) {
    return static_cast<uint64_t>(++publishes);
  });
  std::promise<Outcome> outcome;
  ASSERT_TRUE(
      reloader
          .Start("bad",
                 [&](const Status& status, std::shared_ptr<Engine> engine,
                     uint64_t generation) {
                   outcome.set_value(
                       {status, std::move(engine), generation, false, {}});
                 })
          .ok());
  held.Release();
  const Outcome done = outcome.get_future().get();
  EXPECT_EQ(done.status.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(done.status.message(), "bad dataset");
  EXPECT_EQ(done.engine, nullptr);
  EXPECT_EQ(done.generation, 0u);
  EXPECT_EQ(publishes.load(), 0);
}

TEST(EngineReloaderTest, DestructorWaitsForTheRunningBuild) {
  HeldBuild held;
  std::atomic<bool> published{false};
  auto reloader =
      std::make_unique<EngineReloader>(held.Build(), [&](BuiltDataset) {
        published = true;
        return uint64_t{1};
      });
  ASSERT_TRUE(reloader
                  ->Start("held", [](const Status&, std::shared_ptr<Engine>,
                                     uint64_t) {})
                  .ok());
  held.WaitUntilStarted();
  std::thread releaser([&] { held.Release(); });
  reloader.reset();
  EXPECT_TRUE(published.load());
  releaser.join();
}

}  // namespace
}  // namespace locator
