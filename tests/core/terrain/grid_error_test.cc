// The worst sample of a run: the vectorised scan (FastWorstInRun, AVX2 where
// the processor has it) finds the very sample and error the one-at-a-time
// scan finds, ties (the first wins) and NaN samples included.

#include "server/core/terrain/grid/grid_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace locator {
namespace {

TEST(GridErrorTest, FastWorstInRunFindsWhatOneAtATimeFinds) {
  std::mt19937_64 rng(17);
  // Few distinct values and a flat or gentle plane: many ties.
  std::uniform_int_distribution<int> level(0, 6);
  std::uniform_int_distribution<int> length(1, 40);
  std::vector<float> row(64);
  int ties = 0;
  for (int k = 0; k < 20000; ++k) {
    for (float& v : row) v = static_cast<float>(level(rng));
    if (k % 5 == 0) row[rng() % row.size()] = std::nanf("");
    const int64_t first = static_cast<int64_t>(rng() % 20);
    const int64_t last = first + length(rng) - 1;
    const double base = 0.5 * level(rng);
    const double gx = k % 3 == 0 ? 0.0 : 0.25 * (level(rng) - 3);
    const RunWorst slow = WorstInRun(row.data(), first, last, base, gx);
    const RunWorst fast = FastWorstInRun(row.data(), first, last, base, gx);
    ASSERT_EQ(fast.error, slow.error) << "run " << k;
    ASSERT_EQ(fast.x, slow.x) << "run " << k;
    int at_worst = 0;
    for (int64_t x = first; x <= last; ++x) {
      at_worst +=
          std::abs(base + gx * static_cast<double>(x) - row[x]) == slow.error;
    }
    ties += at_worst > 1 && slow.error > 0;
  }
  EXPECT_GT(ties, 1000);  // the tie-breaking was exercised
}

}  // namespace
}  // namespace locator
