// Waits on observable conditions for tests: polls a predicate (or a
// counter) until it holds, up to a generous bound, so that a test decides on
// what happened and never on how long something took.
//
// Header-only, so that the core tests (built with ThreadSanitizer's flags)
// can use it without linking the rest of locator_testing.
//
// Thread-safety: free functions; the predicates run on the calling thread.

#ifndef LOCATOR_TESTS_TESTING_WAIT_H_
#define LOCATOR_TESTS_TESTING_WAIT_H_

#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>

namespace locator::test {

// Long enough for any condition a test waits on to come true on a loaded,
// sanitized build; only a broken behaviour runs into it.
inline constexpr std::chrono::seconds kGenerousWait{120};

// How often WaitUntil() evaluates its condition.
inline constexpr std::chrono::milliseconds kWaitPoll{5};

// WaitUntilSettled() returns once its counter has read the same this many
// times in a row, kSettledPoll apart.
inline constexpr int kSettledReads = 10;
inline constexpr std::chrono::milliseconds kSettledPoll{50};

// Polls `condition` until it returns true or `timeout` passes; returns its
// last value.
inline bool WaitUntil(const std::function<bool()>& condition,
                      std::chrono::milliseconds timeout = kGenerousWait) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!condition()) {
    if (std::chrono::steady_clock::now() >= deadline) return condition();
    std::this_thread::sleep_for(kWaitPoll);
  }
  return true;
}

// Reads `counter`, which only grows, until it stops moving (kSettledReads
// equal reads) or `timeout` passes; returns the last value. For work that
// ends without a signal the test can see.
inline uint64_t WaitUntilSettled(
    const std::function<uint64_t()>& counter,
    std::chrono::milliseconds timeout = kGenerousWait) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  uint64_t last = counter();
  for (int same = 1;
       same < kSettledReads && std::chrono::steady_clock::now() < deadline;) {
    std::this_thread::sleep_for(kSettledPoll);
    const uint64_t now = counter();
    same = now == last ? same + 1 : 1;
    last = now;
  }
  return last;
}

}  // namespace locator::test

#endif  // LOCATOR_TESTS_TESTING_WAIT_H_
