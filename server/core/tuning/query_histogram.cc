#include "server/core/tuning/query_histogram.h"

#include <algorithm>
#include <cmath>

#include "server/core/geometry/wide_math.h"

namespace locator {

int QueryHistogram::ThreadShard() {
  static std::atomic<int> next{0};
  thread_local const int shard =
      next.fetch_add(1, std::memory_order_relaxed) % kShards;
  return shard;
}

namespace {

// size / (hi - lo); in Wide for a box wider than the largest double, and
// at most the largest double for a box narrower than a few denormals.
double CellsPerUnit(int size, double lo, double hi) {
  const double span = hi - lo;
  const Wide cells =
      std::isfinite(span) ? Wide{size / span} : size / (Wide{hi} - lo);
  return static_cast<double>(std::min(cells, kMaxDouble));
}

}  // namespace

GridGeometry::GridGeometry(const BoundingBox& box, int size)
    : box_(box), size_(size < 1 ? 1 : size) {
  if (!(box_.width() > 0)) box_.max_x = box_.min_x + 1;
  if (!(box_.height() > 0)) box_.max_y = box_.min_y + 1;
  inv_w_ = CellsPerUnit(size_, box_.min_x, box_.max_x);
  inv_h_ = CellsPerUnit(size_, box_.min_y, box_.max_y);
  max_ = std::nextafter(static_cast<double>(size_), 0.0);
}

BoundingBox GridGeometry::CellBox(int column, int row) const {
  return BoundingBox{GridLine(box_.min_x, box_.max_x, column, size_),
                     GridLine(box_.min_y, box_.max_y, row, size_),
                     GridLine(box_.min_x, box_.max_x, column + 1, size_),
                     GridLine(box_.min_y, box_.max_y, row + 1, size_)};
}

QueryHistogram::QueryHistogram(const GridGeometry& grid) : grid_(grid) {
  constexpr size_t kPerLine = 64 / sizeof(std::atomic<uint32_t>);
  stride_ = (grid_.cells() + kPerLine - 1) / kPerLine * kPerLine;
  counts_.reset(new std::atomic<uint32_t>[stride_ * kShards]);
  drained_.reset(new uint32_t[stride_ * kShards]());
  for (size_t i = 0; i < stride_ * kShards; ++i) {
    counts_[i].store(0, std::memory_order_relaxed);
  }
}

void QueryHistogram::AddToCell(size_t cell) {
  const int shard = ThreadShard();
  std::atomic<uint32_t>& counter = counts_[shard * stride_ + cell];
  counter.store(counter.load(std::memory_order_relaxed) + 1,
                std::memory_order_relaxed);
  Track& track = tracks_[shard];
  if (!track.used.load(std::memory_order_relaxed)) {
    track.used.store(true, std::memory_order_relaxed);
  }
  const uint32_t last = track.last.load(std::memory_order_relaxed);
  if (last == cell) return;
  track.last.store(static_cast<uint32_t>(cell), std::memory_order_relaxed);
  const uint32_t g = static_cast<uint32_t>(grid_.size());
  const uint32_t column = static_cast<uint32_t>(cell % g);
  const uint32_t row = static_cast<uint32_t>(cell / g);
  const int direction = column != last % g ? (column > last % g ? 0 : 1)
                                           : (row > last / g ? 2 : 3);
  track.steps[direction].fetch_add(1, std::memory_order_relaxed);
}

CellSteps QueryHistogram::DrainSteps() {
  uint64_t sums[4] = {};
  for (Track& track : tracks_) {
    for (int d = 0; d < 4; ++d) {
      sums[d] += track.steps[d].exchange(0, std::memory_order_relaxed);
    }
  }
  return CellSteps{sums[0], sums[1], sums[2], sums[3]};
}

void QueryHistogram::Drain(std::vector<double>* into) {
  into->resize(grid_.cells(), 0.0);
  for (int s = 0; s < kShards; ++s) {
    // A shard no thread has counted into is all zeros.
    if (!tracks_[s].used.load(std::memory_order_relaxed)) continue;
    for (size_t c = 0; c < grid_.cells(); ++c) {
      const size_t i = s * stride_ + c;
      const uint32_t now = counts_[i].load(std::memory_order_relaxed);
      (*into)[c] += now - drained_[i];
      drained_[i] = now;
    }
  }
}

size_t QueryHistogram::MemoryBytes() const {
  return stride_ * kShards * (sizeof(std::atomic<uint32_t>) + sizeof(uint32_t));
}

}  // namespace locator
