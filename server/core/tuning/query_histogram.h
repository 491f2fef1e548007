// GridGeometry maps points to the cells of a size x size grid over a box;
// QueryHistogram counts queries per cell without serialising readers.
//
// QueryHistogram owns kShards arrays of relaxed-atomic counters. Each thread
// counts into one shard (picked once per thread), so two threads locating at
// once never write the same cache line. A count is a relaxed load and store,
// not a read-modify-write (which would stall every locate): the counters
// only grow, and Drain() returns what each gained since the last drain.
// Threads beyond kShards share shards, and two of them counting the same
// cell at the same instant may lose one count; the tuner needs shares, not
// exact counts.
// Each shard also remembers its last cell and counts the moves between cells
// by direction (CellSteps), so that a sweeping scan can be told from a hot
// spot: a row-order raster moves right ~31 times for every move left.
// A count made during a Drain() lands in this drain or the next.
//
// Thread-safety: Add() from any number of threads; Drain() from one thread at
// a time (the tuner), concurrently with Add().

#ifndef LOCATOR_CORE_QUERY_HISTOGRAM_H_
#define LOCATOR_CORE_QUERY_HISTOGRAM_H_

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "locator/geometry.h"

namespace locator {

class GridGeometry {
 public:
  GridGeometry() = default;
  // A size x size grid over `box`; a degenerate box is widened to 1 unit.
  GridGeometry(const BoundingBox& box, int size);

  int size() const { return size_; }
  size_t cells() const { return static_cast<size_t>(size_) * size_; }
  const BoundingBox& box() const { return box_; }
  // Row-major cell of p; points outside the box map to the nearest cell.
  size_t CellOf(const Point2& p) const {
    return static_cast<size_t>(Row(p.y)) * size_ + Column(p.x);
  }
  // Fractional grid coordinates of p, clamped into [0, size). For a box
  // wider than the largest double, an x further than that from min_x takes
  // the last column (the difference overflows): it only steers walk starts.
  double GridX(double x) const { return Clamp((x - box_.min_x) * inv_w_); }
  double GridY(double y) const { return Clamp((y - box_.min_y) * inv_h_); }
  int Column(double x) const { return static_cast<int>(GridX(x)); }
  int Row(double y) const { return static_cast<int>(GridY(y)); }
  // The rectangle of cell (column, row).
  BoundingBox CellBox(int column, int row) const;
  // A cell's size (infinite for a grid of 1 over a box wider than the
  // largest double), and its width over its height (never NaN).
  double cell_width() const { return 1.0 / inv_w_; }
  double cell_height() const { return 1.0 / inv_h_; }
  double CellAspect() const { return inv_h_ / inv_w_; }

 private:
  // Clamps in double before any integer conversion: far-away (or 1e308)
  // coordinates must never overflow an int.
  double Clamp(double g) const { return g < 0 ? 0 : (g < max_ ? g : max_); }

  BoundingBox box_;
  int size_ = 1;
  double inv_w_ = 1;
  double inv_h_ = 1;
  double max_ = 0;  // the largest double below size_
};

// Moves of consecutive queries (of one shard) from a cell to another, by
// direction along the grid's columns (x) and rows (y).
struct CellSteps {
  uint64_t right = 0;  // to a larger column
  uint64_t left = 0;
  uint64_t up = 0;  // to a larger row
  uint64_t down = 0;
};

class QueryHistogram {
 public:
  static constexpr int kShards = 4;

  explicit QueryHistogram(const GridGeometry& grid);

  // The calling thread's shard: threads are dealt out round-robin the first
  // time they ask, so up to kShards threads never share one.
  static int ThreadShard();

  const GridGeometry& grid() const { return grid_; }
  // Counts one query at p (relaxed; never blocks).
  void Add(const Point2& p) { AddToCell(grid_.CellOf(p)); }
  // The same, for a caller that already knows p's cell.
  void AddToCell(size_t cell);
  // Adds every count since the last Drain() into `into` (size cells()).
  void Drain(std::vector<double>* into);
  // The moves counted since the last call, and resets them.
  CellSteps DrainSteps();
  // Bytes of the counters.
  size_t MemoryBytes() const;

 private:
  // A shard's use, last cell and moves, on a cache line of its own.
  struct alignas(64) Track {
    std::atomic<bool> used{false};  // a thread has counted into the shard
    std::atomic<uint32_t> last{0};
    std::atomic<uint32_t> steps[4] = {};  // right, left, up, down
  };

  GridGeometry grid_;
  std::unique_ptr<std::atomic<uint32_t>[]> counts_;  // kShards * cells
  // counts_ as the last Drain() read them (only Drain() touches it); the
  // difference wraps correctly in uint32_t.
  std::unique_ptr<uint32_t[]> drained_;
  size_t stride_;  // cells rounded up to a cache line
  Track tracks_[kShards];
};

}  // namespace locator

#endif  // LOCATOR_CORE_QUERY_HISTOGRAM_H_
