#include "client/load/cost_windows.h"

#include <gtest/gtest.h>

#include <vector>

namespace locator {
namespace {

TEST(CostWindowsTest, AveragesFullWindowsInArrivalOrder) {
  CostWindows windows(3);
  for (uint32_t cost : {30, 30, 33, 10, 11, 12, 5}) windows.Add(cost);
  EXPECT_EQ(windows.window_size(), 3u);
  // The last window (just "5") is not full and is left out.
  EXPECT_EQ(windows.means(), (std::vector<double>{31, 11}));
}

TEST(CostWindowsTest, NoWindowBeforeTheFirstIsFull) {
  CostWindows windows(500);
  for (int i = 0; i < 499; ++i) windows.Add(7);
  EXPECT_TRUE(windows.means().empty());
  windows.Add(7);
  EXPECT_EQ(windows.means(), (std::vector<double>{7}));
}

}  // namespace
}  // namespace locator
