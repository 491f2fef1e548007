// DatasetRegistry and PointBudget: names resolve to their slots (the
// empty name to the first), an unknown name is NotFound listing the known
// ones, each slot reloads and publishes on its own (a failed build leaves
// its engine and generation, and no other slot sees anything), and the
// point budget is a total that concurrent claims never exceed.

#include "server/datasets/dataset_registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/serving/point_budget.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

std::shared_ptr<Engine> SmallEngine(size_t points, uint64_t seed) {
  StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(GenerateUniform(points, seed), EngineOptions());
  EXPECT_TRUE(engine.ok()) << engine.status().ToString();
  return engine.ok() ? *std::move(engine) : nullptr;
}

const std::vector<DatasetConfig> kDatasets = {
    {"terrain", "uniform:300:1", true},
    {"bedrock", "uniform:400:2", true},
    {"water", "uniform:500:3", true},
};

// Builds "uniform:N:SEED" specs; "bad" fails. Records what each slot built.
class Builds {
 public:
  DatasetBuild Build() {
    return [this](const DatasetSlot& slot, const std::string& spec,
                  Engine* serving, BuiltDataset* built) {
      std::lock_guard<std::mutex> lock(mu_);
      built_[slot.name()].push_back(spec);
      serving_[slot.name()] = serving;
      if (spec == "bad") return Status::InvalidArgument("bad dataset");
      StatusOr<Dataset> dataset = LoadDataset(spec, DatasetLimits());
      if (!dataset.ok()) return dataset.status();
      StatusOr<std::unique_ptr<Engine>> engine =
          Engine::Create(*std::move(dataset), EngineOptions());
      if (!engine.ok()) return engine.status();
      built->engine = *std::move(engine);
      return Status::OK();
    };
  }
  std::vector<std::string> built(const std::string& name) {
    std::lock_guard<std::mutex> lock(mu_);
    return built_[name];
  }
  Engine* serving(const std::string& name) {
    std::lock_guard<std::mutex> lock(mu_);
    return serving_[name];
  }

 private:
  std::mutex mu_;
  std::map<std::string, std::vector<std::string>> built_;
  std::map<std::string, Engine*> serving_;
};

// Reloads `slot` with `spec` and waits for the outcome.
Status ReloadAndWait(DatasetSlot& slot, const std::string& spec) {
  std::promise<Status> outcome;
  const Status started = slot.StartReload(
      spec, [&outcome](const Status& status, std::shared_ptr<Engine>,
                       uint64_t) { outcome.set_value(status); });
  if (!started.ok()) return started;
  return outcome.get_future().get();
}

TEST(DatasetRegistryTest, NamesResolveAndTheFirstIsTheDefault) {
  Builds builds;
  DatasetRegistry registry(kDatasets, "", builds.Build());
  ASSERT_EQ(registry.slots().size(), 3u);
  DatasetSlot* slot = nullptr;
  ASSERT_TRUE(registry.Find("", &slot).ok());
  EXPECT_EQ(slot, &registry.default_slot());
  EXPECT_EQ(slot->name(), "terrain");
  EXPECT_TRUE(slot->is_default());
  ASSERT_TRUE(registry.Find("water", &slot).ok());
  EXPECT_EQ(slot->index(), 2u);
  EXPECT_EQ(slot->spec(), "uniform:500:3");
  EXPECT_FALSE(slot->is_default());
  EXPECT_EQ(slot->serving().engine, nullptr);

  const Status unknown = registry.Find("lava", &slot);
  EXPECT_EQ(unknown.code(), Status::Code::kNotFound);
  EXPECT_EQ(unknown.message(),
            "unknown dataset 'lava'; this server has: terrain (default), "
            "bedrock, water");
  // A long name is cut in the message.
  const Status long_name = registry.Find(std::string(1000, 'x'), &slot);
  EXPECT_EQ(long_name.code(), Status::Code::kNotFound);
  EXPECT_LT(long_name.message().size(), 200u);
}

TEST(DatasetRegistryTest, EachSlotReloadsOnItsOwn) {
  Builds builds;
  DatasetRegistry registry(kDatasets, "", builds.Build());
  for (const auto& slot : registry.slots()) {
    ASSERT_TRUE(ReloadAndWait(*slot, "").ok()) << slot->name();
    EXPECT_EQ(slot->serving().generation, 1u);
  }
  // "" built each slot's own spec.
  EXPECT_EQ(builds.built("bedrock"), std::vector<std::string>{"uniform:400:2"});
  DatasetSlot& terrain = *registry.slots()[0];
  DatasetSlot& bedrock = *registry.slots()[1];
  const std::shared_ptr<Engine> terrain_engine = terrain.serving().engine;
  const std::shared_ptr<Engine> bedrock_engine = bedrock.serving().engine;
  EXPECT_EQ(bedrock_engine->dataset_info().input_points, 400u);

  // A reload of bedrock: a new engine there, terrain untouched.
  ASSERT_TRUE(ReloadAndWait(bedrock, "uniform:450:9").ok());
  EXPECT_EQ(builds.serving("bedrock"), bedrock_engine.get());
  EXPECT_EQ(bedrock.serving().generation, 2u);
  EXPECT_EQ(bedrock.serving().engine->dataset_info().input_points, 450u);
  EXPECT_EQ(terrain.serving().engine, terrain_engine);
  EXPECT_EQ(terrain.serving().generation, 1u);

  // A failed reload of terrain leaves it as it was, and bedrock too.
  const std::shared_ptr<Engine> bedrock_now = bedrock.serving().engine;
  EXPECT_EQ(ReloadAndWait(terrain, "bad").code(),
            Status::Code::kInvalidArgument);
  EXPECT_EQ(terrain.serving().engine, terrain_engine);
  EXPECT_EQ(terrain.serving().generation, 1u);
  EXPECT_EQ(bedrock.serving().engine, bedrock_now);
  EXPECT_EQ(bedrock.serving().generation, 2u);
}

TEST(DatasetRegistryTest, ReloadsOfDifferentSlotsRunAtOnce) {
  // The builds are held until released; both have started before either
  // ends, which one build at a time across slots could never do.
  std::promise<void> both_started;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<int> started{0};
  DatasetRegistry registry(kDatasets, "",
                           [&](const DatasetSlot& slot, const std::string&,
                               Engine*, BuiltDataset* built) {
                             if (++started == 2) both_started.set_value();
                             released.wait();
                             built->engine =
                                 SmallEngine(100 + slot.index(), slot.index());
                             return Status::OK();
                           });
  std::promise<void> first_done, second_done;
  ASSERT_TRUE(registry.slots()[0]
                  ->StartReload("", [&](const Status&, std::shared_ptr<Engine>,
                                        uint64_t) { first_done.set_value(); })
                  .ok());
  ASSERT_TRUE(registry.slots()[1]
                  ->StartReload("", [&](const Status&, std::shared_ptr<Engine>,
                                        uint64_t) { second_done.set_value(); })
                  .ok());
  both_started.get_future().wait();
  EXPECT_TRUE(registry.slots()[0]->reload_in_progress());
  EXPECT_TRUE(registry.slots()[1]->reload_in_progress());
  EXPECT_FALSE(registry.slots()[2]->reload_in_progress());
  // A slot still refuses a second build of its own.
  EXPECT_EQ(registry.slots()[0]
                ->StartReload(
                    "", [](const Status&, std::shared_ptr<Engine>, uint64_t) {})
                .message(),
            "reload in progress");
  release.set_value();
  first_done.get_future().wait();
  second_done.get_future().wait();
  EXPECT_EQ(registry.slots()[0]->serving().generation, 1u);
  EXPECT_EQ(registry.slots()[1]->serving().generation, 1u);
  EXPECT_EQ(registry.slots()[2]->serving().engine, nullptr);
}

TEST(PointBudgetTest, ATotalSharedByTheDatasets) {
  PointBudget budget(1000, 3);
  EXPECT_EQ(budget.Available(0), 1000u);
  ASSERT_TRUE(budget.Claim(0, 600).ok());
  budget.Commit(0);
  EXPECT_EQ(budget.Available(1), 400u);
  EXPECT_EQ(budget.HeldByOthers(1), 600u);
  // A dataset's own holding does not count against its next build.
  EXPECT_EQ(budget.Available(0), 1000u);

  const Status over = budget.Claim(1, 401);
  EXPECT_EQ(over.code(), Status::Code::kResourceExhausted);
  EXPECT_EQ(over.message(),
            "401 points would take the datasets' total beyond 1000 (the other "
            "datasets hold 600)");
  ASSERT_TRUE(budget.Claim(1, 400).ok());
  budget.Commit(1);
  EXPECT_EQ(budget.Available(2), 0u);
  EXPECT_EQ(budget.Held(), 1000u);
}

TEST(PointBudgetTest, ABuildHoldsItsPointsBesideTheServingOnes) {
  PointBudget budget(1000, 2);
  ASSERT_TRUE(budget.Claim(0, 600).ok());
  budget.Commit(0);
  // Dataset 0 reloads a smaller dataset: while it builds it still holds
  // the 600 it serves, so dataset 1 may not take more than 400.
  ASSERT_TRUE(budget.Claim(0, 100).ok());
  EXPECT_EQ(budget.Available(1), 400u);
  // A failed build leaves the 600.
  budget.Cancel(0);
  EXPECT_EQ(budget.Available(1), 400u);
  // A successful one frees 500.
  ASSERT_TRUE(budget.Claim(0, 100).ok());
  budget.Commit(0);
  EXPECT_EQ(budget.Available(1), 900u);
  // A larger build holds the larger count at once.
  ASSERT_TRUE(budget.Claim(0, 700).ok());
  EXPECT_EQ(budget.Available(1), 300u);
  EXPECT_EQ(budget.Claim(1, 301).code(), Status::Code::kResourceExhausted);
}

TEST(PointBudgetTest, ConcurrentBuildsNeverTakeMoreThanTheTotal) {
  constexpr uint64_t kTotal = 1000;
  constexpr size_t kDatasets = 8;
  PointBudget budget(kTotal, kDatasets);
  std::atomic<bool> exceeded{false};
  std::vector<std::thread> threads;
  for (size_t d = 0; d < kDatasets; ++d) {
    threads.emplace_back([&, d] {
      for (uint64_t round = 0; round < 2000; ++round) {
        const uint64_t want = (round * 37 + d * 11) % 300;
        if (!budget.Claim(d, std::min(want, budget.Available(d))).ok()) {
          continue;
        }
        if (budget.Held() > kTotal) exceeded = true;
        if (round % 3 == 0) {
          budget.Cancel(d);
        } else {
          budget.Commit(d);
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_FALSE(exceeded.load());
  EXPECT_LE(budget.Held(), kTotal);
  EXPECT_GT(budget.Held(), 0u);
}

}  // namespace
}  // namespace locator
