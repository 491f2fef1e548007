// InFlight: what it counts ends before WaitUntilNone() returns, counted
// items included, whichever thread lets go of them.

#include "common/in_flight.h"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

namespace locator {
namespace {

// Notes its own deletion.
struct Item {
  explicit Item(std::atomic<int>* deleted) : deleted(deleted) {}
  ~Item() { deleted->fetch_add(1); }
  std::atomic<int>* deleted;
};

TEST(InFlightTest, NothingInFlightDoesNotWait) {
  InFlight in_flight;
  in_flight.WaitUntilNone();
  in_flight.Add();
  in_flight.Remove();
  in_flight.WaitUntilNone();
}

TEST(InFlightTest, ACountedItemIsInFlightUntilItsLastHolderLetsGo) {
  InFlight in_flight;
  std::atomic<int> deleted = 0;
  std::shared_ptr<Item> item =
      in_flight.Counted(std::make_unique<Item>(&deleted));
  std::shared_ptr<Item> another_holder = item;
  item.reset();
  EXPECT_EQ(deleted, 0);
  another_holder.reset();
  EXPECT_EQ(deleted, 1);
  in_flight.WaitUntilNone();
}

TEST(InFlightTest, WaitingEndsOnlyAfterItemsLetGoOnOtherThreadsAreDeleted) {
  constexpr int kItems = 64;
  for (int round = 0; round < 20; ++round) {
    InFlight in_flight;
    std::atomic<int> deleted = 0;
    std::vector<std::thread> holders;
    for (int i = 0; i < kItems; ++i) {
      holders.emplace_back(
          [item = in_flight.Counted(std::make_unique<Item>(&deleted))] {});
    }
    in_flight.WaitUntilNone();
    // Deleted before they stopped counting: never fewer.
    EXPECT_EQ(deleted, kItems);
    for (std::thread& holder : holders) holder.join();
  }
}

}  // namespace
}  // namespace locator
