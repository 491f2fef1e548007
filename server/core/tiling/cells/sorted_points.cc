#include "server/core/tiling/cells/sorted_points.h"

#include <algorithm>
#include <tuple>

#include "server/core/mesh/radix_sort.h"
#include "server/core/tiling/cells/parallel.h"

namespace locator {

namespace {

// Whether input point `index` repeats an earlier point of its key group
// [group, group + size) (sorted by input index).
class RepeatFinder {
 public:
  explicit RepeatFinder(std::span<const Point2> input) : input_(input) {}

  // Marks repeated[k] for every entry of the group that repeats an earlier
  // one. Small groups compare pairwise; large ones (many points in one
  // 2^16 cell) sort by coordinates.
  void Mark(const uint64_t* group, size_t size, std::vector<bool>* repeated) {
    constexpr size_t kPairwise = 16;
    repeated->assign(size, false);
    if (size <= kPairwise) {
      for (size_t k = 1; k < size; ++k) {
        for (size_t j = 0; j < k && !(*repeated)[k]; ++j) {
          (*repeated)[k] = Same(group[j], group[k]);
        }
      }
      return;
    }
    order_.resize(size);
    for (size_t k = 0; k < size; ++k) order_[k] = static_cast<uint32_t>(k);
    std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) {
      const Point2& p = Point(group[a]);
      const Point2& q = Point(group[b]);
      return std::tie(p.x, p.y, a) < std::tie(q.x, q.y, b);
    });
    for (size_t k = 1; k < size; ++k) {
      (*repeated)[order_[k]] = Same(group[order_[k - 1]], group[order_[k]]);
    }
  }

 private:
  const Point2& Point(uint64_t item) const {
    return input_[static_cast<uint32_t>(item)];
  }
  bool Same(uint64_t a, uint64_t b) const {
    return Point(a).x == Point(b).x && Point(a).y == Point(b).y;
  }

  std::span<const Point2> input_;
  std::vector<uint32_t> order_;
};

}  // namespace

void AppendDistinct(std::span<const uint64_t> items,
                    std::span<const Point2> input, const CellGrid& grid,
                    LargeVector<Point2>* points, LargeVector<uint32_t>* indices,
                    std::span<uint32_t> cell_sizes) {
  const size_t n = items.size();
  RepeatFinder finder(input);
  std::vector<bool> repeated;
  for (size_t group = 0; group < n;) {
    const uint32_t key = static_cast<uint32_t>(items[group] >> 32);
    size_t end = group + 1;
    while (end < n && static_cast<uint32_t>(items[end] >> 32) == key) ++end;
    const bool single = end - group == 1;  // most keys: nothing to merge
    if (!single) finder.Mark(&items[group], end - group, &repeated);
    const uint32_t cell = grid.CellOfKey(key);
    for (size_t k = group; k < end; ++k) {
      if (!single && repeated[k - group]) continue;
      const auto index = static_cast<uint32_t>(items[k]);
      points->push_back(input[index]);
      indices->push_back(index);
      ++cell_sizes[cell];
    }
    group = end;
  }
}

void SortPoints(std::span<const Point2> input, size_t per_cell,
                unsigned threads, SortedPoints* out) {
  const size_t n = input.size();
  BoundingBox box;
  for (const Point2& p : input) box.Extend(p);
  out->grid = CellGrid(box, CellGrid::LevelFor(n, per_cell));
  out->input_points = n;

  LargeVector<uint64_t> items(n);
  ParallelSlices(n, threads, [&](size_t begin, size_t end, size_t) {
    for (size_t i = begin; i < end; ++i) {
      items[i] = uint64_t{out->grid.FineKey(input[i])} << 32 | i;
    }
  });
  SortByHighHalf(&items);

  out->points.clear();
  out->ids.clear();
  out->points.reserve(n);
  out->ids.reserve(n);
  out->cell_start.assign(out->grid.num_cells() + 1, 0);
  AppendDistinct(items, input, out->grid, &out->points, &out->ids,
                 std::span<uint32_t>(out->cell_start).subspan(1));
  for (size_t c = 1; c < out->cell_start.size(); ++c) {
    out->cell_start[c] += out->cell_start[c - 1];
  }
  out->points.shrink_to_fit();
  out->ids.shrink_to_fit();
}

}  // namespace locator
