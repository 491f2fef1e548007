// SimplifyCutLines (grid_tiles.h): the samples the tiles share.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "server/core/terrain/grid/grid_tiles.h"

namespace locator {

namespace {

// A full-length cut line: column `at` (vertical) or row `at`. Sample i is
// its i-th point; edge i runs from sample i to sample i + 1 between the
// cell on side 0 (left or above) and the cell on side 1 (right or below).
class CutLine {
 public:
  CutLine(const ElevationGrid& grid, const CellMask& mask, bool vertical,
          int64_t at)
      : grid_(grid),
        mask_(mask),
        vertical_(vertical),
        at_(at),
        length_(vertical ? grid.height : grid.width) {}

  int64_t length() const { return length_; }
  GridPoint Point(int64_t i) const {
    return vertical_ ? GridPoint{at_, i} : GridPoint{i, at_};
  }
  double Value(int64_t i) const {
    const GridPoint p = Point(i);
    return grid_.ValueAt(static_cast<uint32_t>(p.x),
                         static_cast<uint32_t>(p.y));
  }
  // Whether the cell on `side` of edge i is valid (false past the ends).
  bool SideValid(int side, int64_t i) const {
    return vertical_ ? mask_.Valid(at_ - 1 + side, i)
                     : mask_.Valid(i, at_ - 1 + side);
  }
  bool Active(int64_t i) const { return SideValid(0, i) || SideValid(1, i); }

  // Appends to *kept the samples strictly between a and b that keep every
  // sample of [a, b] within max_error of the linear interpolation between
  // the kept ones: the worst sample first, recursively on both halves.
  void Refine(int64_t a, int64_t b, double max_error,
              std::vector<int64_t>* kept) const {
    std::vector<std::pair<int64_t, int64_t>> stack = {{a, b}};
    while (!stack.empty()) {
      const auto [lo, hi] = stack.back();
      stack.pop_back();
      const double z_lo = Value(lo);
      const double slope = (Value(hi) - z_lo) / static_cast<double>(hi - lo);
      double worst = max_error;
      int64_t worst_i = -1;
      for (int64_t i = lo + 1; i < hi; ++i) {
        const double e =
            std::abs(z_lo + slope * static_cast<double>(i - lo) - Value(i));
        if (e > worst) {
          worst = e;
          worst_i = i;
        }
      }
      if (worst_i < 0) continue;
      kept->push_back(worst_i);
      stack.emplace_back(lo, worst_i);
      stack.emplace_back(worst_i, hi);
    }
  }

 private:
  const ElevationGrid& grid_;
  const CellMask& mask_;
  const bool vertical_;
  const int64_t at_;
  const int64_t length_;
};

// Appends line's kept samples to *out.
void SimplifyLine(const CutLine& line, const std::vector<int64_t>& crossings,
                  double max_error, std::vector<GridPoint>* out) {
  std::vector<int64_t> kept;
  int64_t last_break = -1;
  for (int64_t i = 0; i < line.length(); ++i) {
    const bool before = line.Active(i - 1);
    const bool after = line.Active(i);
    if (!before && !after) continue;
    // A break: a run of the line's domain edges starts or ends, the
    // boundary on either side turns, or another cut line crosses.
    const bool breaks =
        before != after || line.SideValid(0, i - 1) != line.SideValid(0, i) ||
        line.SideValid(1, i - 1) != line.SideValid(1, i) ||
        std::binary_search(crossings.begin(), crossings.end(), i);
    if (!breaks) continue;
    if (before && last_break >= 0) {
      line.Refine(last_break, i, max_error, &kept);
    }
    kept.push_back(i);
    last_break = i;
  }
  std::sort(kept.begin(), kept.end());
  for (const int64_t i : kept) out->push_back(line.Point(i));
}

}  // namespace

std::vector<GridPoint> SimplifyCutLines(const ElevationGrid& grid,
                                        const CellMask& mask,
                                        const TilePlan& plan,
                                        double max_error) {
  std::vector<GridPoint> points;
  for (const int64_t col : plan.cut_cols) {
    SimplifyLine(CutLine(grid, mask, true, col), plan.cut_rows, max_error,
                 &points);
  }
  for (const int64_t row : plan.cut_rows) {
    SimplifyLine(CutLine(grid, mask, false, row), plan.cut_cols, max_error,
                 &points);
  }
  const auto by_row = [](const GridPoint& a, const GridPoint& b) {
    return std::pair(a.y, a.x) < std::pair(b.y, b.x);
  };
  std::sort(points.begin(), points.end(), by_row);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

}  // namespace locator
