#include "server/http/api_lane.h"

#include <gtest/gtest.h>
#include <prometheus/gauge.h>
#include <prometheus/registry.h>

#include <future>
#include <thread>
#include <vector>

namespace locator {
namespace {

class ApiLaneTest : public ::testing::Test {
 protected:
  double Running() { return running_.Add({{"lane", "test"}}).Value(); }
  double Waiting() { return waiting_.Add({{"lane", "test"}}).Value(); }

  prometheus::Registry registry_;
  prometheus::Family<prometheus::Gauge>& running_ =
      prometheus::BuildGauge().Name("running").Register(registry_);
  prometheus::Family<prometheus::Gauge>& waiting_ =
      prometheus::BuildGauge().Name("waiting").Register(registry_);
};

// One thread, two places: while a call runs and two wait, a fourth is
// refused at once, on the caller's thread; once the queue moves, calls are
// admitted again, and every admitted call runs, in order.
TEST_F(ApiLaneTest, ACallFindingEveryPlaceTakenIsRefusedAtOnce) {
  ApiLane lane("test", 1, 2, running_, waiting_);
  EXPECT_EQ(lane.name(), "test");
  EXPECT_EQ(lane.max_waiting(), 2u);
  std::promise<void> started, release;
  std::shared_future<void> released = release.get_future().share();
  lane.Submit([&](bool admitted) {
    EXPECT_TRUE(admitted);
    started.set_value();
    released.wait();
  });
  started.get_future().wait();
  // Written by the lane's thread only, read after `done`.
  std::vector<int> ran;
  std::promise<void> done;
  for (int i : {1, 2}) {
    lane.Submit([&, i](bool admitted) {
      EXPECT_TRUE(admitted) << i;
      ran.push_back(i);
      if (i == 2) done.set_value();
    });
  }
  EXPECT_EQ(Running(), 1);
  EXPECT_EQ(Waiting(), 2);
  bool refused = false;
  std::thread::id refused_on;
  lane.Submit([&](bool admitted) {
    refused = !admitted;
    refused_on = std::this_thread::get_id();
  });
  EXPECT_TRUE(refused);
  EXPECT_EQ(refused_on, std::this_thread::get_id());
  EXPECT_EQ(Waiting(), 2);

  release.set_value();
  done.get_future().wait();
  EXPECT_EQ(ran, (std::vector<int>{1, 2}));
  std::promise<bool> later;
  lane.Submit([&](bool admitted) { later.set_value(admitted); });
  EXPECT_TRUE(later.get_future().get());
}

}  // namespace
}  // namespace locator
