#include "server/core/tiling/cells/halo_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace locator {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

HaloCells::HaloCells(const CellGrid& grid, const CellSource& source)
    : grid_(grid), source_(source), state_(grid.num_cells(), kUnknown) {
  const BoundingBox& box = grid.box();
  slack_ = 1e-12 * (std::abs(box.min_x) + std::abs(box.max_x) +
                    std::abs(box.min_y) + std::abs(box.max_y));
}

void HaloCells::Clear() {
  for (const size_t index : touched_) state_[index] = kUnknown;
  touched_.clear();
  wanted_.clear();
  wanted_index_.clear();
}

bool HaloCells::WindowIsGrid() const {
  const uint32_t last = grid_.side() - 1;
  return window_.min_column == 0 && window_.min_row == 0 &&
         window_.max_column == last && window_.max_row == last;
}

void HaloCells::SetState(size_t index, State state) {
  if (state_[index] == kUnknown) touched_.push_back(index);
  state_[index] = state;
}

void HaloCells::MarkSeen(uint32_t column, uint32_t row) {
  SetState(Index(column, row), kSeen);
}

void HaloCells::CoverCells(uint32_t row, uint32_t c0, uint32_t c1,
                           Cover* cover) {
  if (row < window_.min_row || row > window_.max_row ||
      c0 < window_.min_column || c1 > window_.max_column) {
    cover->beyond = true;
    cover->covered = false;
    if (row < window_.min_row || row > window_.max_row) return;
  }
  const uint32_t first = std::max(c0, window_.min_column);
  const uint32_t last = std::min(c1, window_.max_column);
  for (uint32_t column = first; column <= last; ++column) {
    const size_t index = Index(column, row);
    switch (state_[index]) {
      case kSeen:
        break;
      case kWanted:
        cover->covered = false;
        break;
      case kUnknown: {
        const uint32_t cell = grid_.Cell(column, row);
        if (source_.CellSize(cell) == 0) {
          SetState(index, kSeen);
          break;
        }
        SetState(index, kWanted);
        wanted_.push_back(cell);
        wanted_index_.push_back(index);
        cover->covered = false;
        break;
      }
    }
  }
}

void HaloCells::CoverSpan(uint32_t row, double x0, double x1, Cover* cover) {
  CoverCells(row, grid_.Column(x0 - slack_), grid_.Column(x1 + slack_), cover);
}

HaloCells::Cover HaloCells::CoverBox(const Window& box) {
  Cover cover;
  for (uint32_t row = box.min_row; row <= box.max_row; ++row) {
    CoverCells(row, box.min_column, box.max_column, &cover);
  }
  return cover;
}

bool HaloCells::AllSeen(const Window& box) const {
  constexpr uint32_t kMostCells = 16;
  if ((box.max_column - box.min_column + 1) * (box.max_row - box.min_row + 1) >
      kMostCells) {
    return false;
  }
  for (uint32_t row = box.min_row; row <= box.max_row; ++row) {
    for (uint32_t column = box.min_column; column <= box.max_column; ++column) {
      if (state_[Index(column, row)] != kSeen) return false;
    }
  }
  return true;
}

HaloCells::Cover HaloCells::CoverWindow() {
  Cover cover = CoverBox(window_);
  if (!WindowIsGrid()) {
    cover.beyond = true;
    cover.covered = false;
  }
  return cover;
}

HaloCells::Cover HaloCells::CoverDisk(const Disk& disk) {
  Cover cover;
  const Point2& c = disk.center;
  // Every rounding below is within a relative 1e-15 of these magnitudes:
  // the radius grows by far more, and distances shrink by as much.
  const double extra =
      slack_ + 1e-12 * (std::abs(c.x) + std::abs(c.y) + disk.radius);
  const double r = disk.radius + extra;
  const uint32_t first = grid_.Row(c.y - r);
  const uint32_t last = grid_.Row(c.y + r);
  // Most disks are small, in cells seen long ago: their bounding box is.
  const uint32_t c0 = grid_.Column(c.x - r - slack_);
  const uint32_t c1 = grid_.Column(c.x + r + slack_);
  if (AllSeen({c0, first, c1, last})) return cover;
  for (uint32_t row = first; row <= last; ++row) {
    const CellGrid::Interval span = grid_.RowSpan(row);
    // The distance from the centre to the band, shortened by the slack.
    double dy = c.y < span.lo   ? span.lo - c.y
                : c.y > span.hi ? c.y - span.hi
                                : 0;
    dy = std::max(0.0, dy - extra);
    if (dy > r) continue;
    // Two roots, not the root of a product that may underflow.
    double half = std::sqrt(r - dy) * std::sqrt(r + dy) * (1 + 1e-12);
    if (!(half >= 0)) half = kInfinity;
    CoverSpan(row, c.x - half, c.x + half, &cover);
  }
  return cover;
}

HaloCells::Cover HaloCells::CoverRightOf(const Point2& p, const Point2& q) {
  const double dx = q.x - p.x;
  const double dy = q.y - p.y;
  if (!std::isfinite(dx) || !std::isfinite(dy)) {
    Window grid{0, 0, grid_.side() - 1, grid_.side() - 1};
    return CoverBox(grid);
  }
  Cover cover;
  // x on the line at height y (the line is not horizontal here).
  const auto line_x = [&](double y) {
    return dx == 0 ? p.x : p.x + dx * ((y - p.y) / dy);
  };
  for (uint32_t row = 0; row < grid_.side(); ++row) {
    const CellGrid::Interval span = grid_.RowSpan(row);
    double x0 = -kInfinity;
    double x1 = kInfinity;
    if (dy == 0) {
      // Right of a rightward line is below it, of a leftward one above.
      const bool meets =
          dx > 0 ? span.lo <= p.y + slack_ : span.hi >= p.y - slack_;
      if (!meets) continue;
    } else {
      const double a = line_x(span.lo);
      const double b = line_x(span.hi);
      const double margin = 1e-12 * (std::abs(a) + std::abs(b));
      if (std::isnan(a) || std::isnan(b)) {
        // The whole row.
      } else if (dy > 0) {
        x0 = std::min(a, b) - margin;  // right of an upward line: x beyond
      } else {
        x1 = std::max(a, b) + margin;
      }
    }
    CoverSpan(row, x0, x1, &cover);
  }
  return cover;
}

std::vector<uint32_t> HaloCells::TakeWanted() {
  for (const size_t index : wanted_index_) state_[index] = kSeen;
  wanted_index_.clear();
  std::vector<uint32_t> cells;
  cells.swap(wanted_);
  return cells;
}

}  // namespace locator
