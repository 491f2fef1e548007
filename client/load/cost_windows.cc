#include "client/load/cost_windows.h"

namespace locator {

CostWindows::CostWindows(uint64_t window_size) : window_size_(window_size) {}

void CostWindows::Add(uint32_t cost) {
  sum_ += cost;
  if (++filled_ < window_size_) return;
  means_.push_back(static_cast<double>(sum_) / static_cast<double>(filled_));
  filled_ = 0;
  sum_ = 0;
}

}  // namespace locator
