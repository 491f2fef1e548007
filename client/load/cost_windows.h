// CostWindows: the server's mean cost per window of consecutive queries, in
// the order the answers arrived. It shows how the server's cost falls as its
// tuning warms up (the self-tuning strategy re-tunes after its first ~2000
// queries), so warm-up queries count here too.
//
// Owns the means of the windows filled so far. Thread-safety: not
// thread-safe; RunRecorder serializes calls.

#ifndef LOCATOR_CLIENT_LOAD_COST_WINDOWS_H_
#define LOCATOR_CLIENT_LOAD_COST_WINDOWS_H_

#include <cstdint>
#include <vector>

namespace locator {

class CostWindows {
 public:
  // Windows of `window_size` (> 0) queries each.
  explicit CostWindows(uint64_t window_size);

  uint64_t window_size() const { return window_size_; }
  // Adds the cost of the next query to arrive.
  void Add(uint32_t cost);
  // The mean cost of each full window, oldest first. A partly filled last
  // window is left out so every mean covers the same number of queries.
  const std::vector<double>& means() const { return means_; }

 private:
  const uint64_t window_size_;
  uint64_t filled_ = 0;  // queries in the current window
  uint64_t sum_ = 0;     // their total cost
  std::vector<double> means_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_COST_WINDOWS_H_
