#include "server/core/tuning/hot_regions.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace locator {

namespace {

// A rectangle of grid cells, columns [c0, c1] x rows [r0, r1].
struct CellRect {
  int c0, r0, c1, r1;
  long area() const { return long{c1 - c0 + 1} * (r1 - r0 + 1); }
};

CellRect Union(const CellRect& a, const CellRect& b) {
  return CellRect{std::min(a.c0, b.c0), std::min(a.r0, b.r0),
                  std::max(a.c1, b.c1), std::max(a.r1, b.r1)};
}

std::vector<CellRect> CoverByMaximalRectangles(std::vector<char> hot, int g) {
  std::vector<CellRect> rects;
  for (int r = 0; r < g; ++r) {
    for (int c = 0; c < g; ++c) {
      if (!hot[r * g + c]) continue;
      int c1 = c;
      while (c1 + 1 < g && hot[r * g + c1 + 1]) ++c1;
      int r1 = r;
      auto row_hot = [&](int row) {
        for (int k = c; k <= c1; ++k) {
          if (!hot[row * g + k]) return false;
        }
        return true;
      };
      while (r1 + 1 < g && row_hot(r1 + 1)) ++r1;
      for (int rr = r; rr <= r1; ++rr) {
        std::fill(hot.begin() + rr * g + c, hot.begin() + rr * g + c1 + 1, 0);
      }
      rects.push_back(CellRect{c, r, c1, r1});
    }
  }
  return rects;
}

void MergeDownTo(size_t max_regions, std::vector<CellRect>* rects) {
  while (rects->size() > std::max<size_t>(max_regions, 1)) {
    long best_waste = std::numeric_limits<long>::max();
    size_t bi = 0, bj = 1;
    for (size_t i = 0; i < rects->size(); ++i) {
      for (size_t j = i + 1; j < rects->size(); ++j) {
        const long waste = Union((*rects)[i], (*rects)[j]).area() -
                           (*rects)[i].area() - (*rects)[j].area();
        if (waste < best_waste) {
          best_waste = waste;
          bi = i;
          bj = j;
        }
      }
    }
    (*rects)[bi] = Union((*rects)[bi], (*rects)[bj]);
    rects->erase(rects->begin() + bj);
  }
}

}  // namespace

std::vector<BoundingBox> FindHotRegions(const GridGeometry& grid,
                                        const std::vector<double>& counts,
                                        const HotRegionOptions& options) {
  const int g = grid.size();
  const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
  const double threshold = std::max(
      options.min_count, options.density_factor * total / grid.cells());
  std::vector<char> hot(grid.cells(), 0);
  for (size_t c = 0; c < grid.cells(); ++c) hot[c] = counts[c] >= threshold;

  std::vector<CellRect> rects = CoverByMaximalRectangles(std::move(hot), g);
  MergeDownTo(options.max_regions, &rects);

  std::vector<BoundingBox> boxes;
  boxes.reserve(rects.size());
  for (const CellRect& r : rects) {
    const BoundingBox lo = grid.CellBox(r.c0, r.r0);
    const BoundingBox hi = grid.CellBox(r.c1, r.r1);
    boxes.push_back(BoundingBox{lo.min_x, lo.min_y, hi.max_x, hi.max_y});
  }
  return boxes;
}

}  // namespace locator
