#include "server/core/query_histogram.h"

#include <cmath>

namespace locator {

namespace {

// The shard of the calling thread: threads are dealt out round-robin the
// first time they count, so up to kShards threads never share a counter.
int ThreadShard() {
  static std::atomic<int> next{0};
  thread_local const int shard =
      next.fetch_add(1, std::memory_order_relaxed) % QueryHistogram::kShards;
  return shard;
}

}  // namespace

GridGeometry::GridGeometry(const BoundingBox& box, int size)
    : box_(box), size_(size < 1 ? 1 : size) {
  if (!(box_.width() > 0)) box_.max_x = box_.min_x + 1;
  if (!(box_.height() > 0)) box_.max_y = box_.min_y + 1;
  inv_w_ = size_ / box_.width();
  inv_h_ = size_ / box_.height();
  max_ = std::nextafter(static_cast<double>(size_), 0.0);
}

BoundingBox GridGeometry::CellBox(int column, int row) const {
  const double w = box_.width() / size_;
  const double h = box_.height() / size_;
  return BoundingBox{box_.min_x + column * w, box_.min_y + row * h,
                     box_.min_x + (column + 1) * w, box_.min_y + (row + 1) * h};
}

QueryHistogram::QueryHistogram(const GridGeometry& grid) : grid_(grid) {
  constexpr size_t kPerLine = 64 / sizeof(std::atomic<uint32_t>);
  stride_ = (grid_.cells() + kPerLine - 1) / kPerLine * kPerLine;
  counts_.reset(new std::atomic<uint32_t>[stride_ * kShards]);
  for (size_t i = 0; i < stride_ * kShards; ++i) {
    counts_[i].store(0, std::memory_order_relaxed);
  }
}

void QueryHistogram::AddToCell(size_t cell) {
  counts_[ThreadShard() * stride_ + cell].fetch_add(1,
                                                    std::memory_order_relaxed);
}

void QueryHistogram::Drain(std::vector<double>* into) {
  into->resize(grid_.cells(), 0.0);
  for (int s = 0; s < kShards; ++s) {
    for (size_t c = 0; c < grid_.cells(); ++c) {
      // Most cells of clustered traffic are empty: read before writing.
      std::atomic<uint32_t>& counter = counts_[s * stride_ + c];
      if (counter.load(std::memory_order_relaxed) == 0) continue;
      (*into)[c] += counter.exchange(0, std::memory_order_relaxed);
    }
  }
}

size_t QueryHistogram::MemoryBytes() const {
  return stride_ * kShards * sizeof(std::atomic<uint32_t>);
}

}  // namespace locator
