#include "server/core/terrain/grid/grid_domain.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "server/core/cgal/cdt_with_info.h"

namespace locator {

namespace {

using Cdt = CdtWithInfo<uint32_t, uint32_t>;

constexpr uint32_t kOutside = 0xffffffffu;

// Bit i of `words` set for each valid sample of `row` (NaN is nodata).
void SampleBits(const ElevationGrid& grid, uint32_t row,
                std::vector<uint64_t>* words) {
  const float* values = grid.values.data() + grid.Index(0, row);
  for (uint32_t word = 0; word * 64 < grid.width; ++word) {
    const uint32_t end = std::min(grid.width, (word + 1) * 64);
    uint64_t bits = 0;
    for (uint32_t col = word * 64; col < end; ++col) {
      bits |= uint64_t{values[col] == values[col]} << (col % 64);  // not NaN
    }
    (*words)[word] = bits;
  }
}

// Bit i of the result is bit i - 1 of `words` (the bit to the left).
uint64_t ShiftedWord(const std::vector<uint64_t>& words, size_t w) {
  return (words[w] << 1) | (w > 0 ? words[w - 1] >> 63 : 0);
}

// Bit i of the result is bit i + 1 of `words` (the bit to the right).
uint64_t NextBitsWord(const std::vector<uint64_t>& words, size_t w) {
  return (words[w] >> 1) | (w + 1 < words.size() ? words[w + 1] << 63 : 0);
}

}  // namespace

CellMask::CellMask(const ElevationGrid& grid)
    : cols_(int64_t{grid.width} - 1),
      rows_(int64_t{grid.height} - 1),
      words_per_row_((grid.width + 63) / 64) {
  bits_.assign(
      static_cast<size_t>(words_per_row_ * std::max<int64_t>(rows_, 0)), 0);
  std::vector<uint64_t> above(words_per_row_), below(words_per_row_);
  if (grid.height > 0) SampleBits(grid, 0, &below);
  // A cell is valid when the samples at both ends of its top and bottom
  // edges are: AND two sample rows, then each bit with its right neighbour.
  for (int64_t row = 0; row < rows_; ++row) {
    std::swap(above, below);
    SampleBits(grid, static_cast<uint32_t>(row + 1), &below);
    std::vector<uint64_t> both(words_per_row_);
    for (int64_t w = 0; w < words_per_row_; ++w) both[w] = above[w] & below[w];
    uint64_t* cells = bits_.data() + row * words_per_row_;
    for (int64_t w = 0; w < words_per_row_; ++w) {
      cells[w] = both[w] & NextBitsWord(both, w);
      if ((w + 1) * 64 > cols_) {  // no cell at or past column cols_
        const int64_t keep = cols_ - w * 64;
        cells[w] &=
            keep <= 0 ? 0
                      : (keep >= 64 ? ~uint64_t{0} : (uint64_t{1} << keep) - 1);
      }
      valid_cells_ += std::popcount(cells[w]);
    }
  }
  // A valid sample is served when one of the (up to) four cells around it
  // is valid: those of cell rows row - 1 and row, columns col - 1 and col.
  std::vector<uint64_t> samples(words_per_row_);
  for (int64_t row = 0; row <= rows_; ++row) {
    SampleBits(grid, static_cast<uint32_t>(row), &samples);
    std::vector<uint64_t> cells(words_per_row_, 0);
    for (const int64_t r : {row - 1, row}) {
      if (r < 0 || r >= rows_) continue;
      for (int64_t w = 0; w < words_per_row_; ++w) {
        cells[w] |= bits_[r * words_per_row_ + w];
      }
    }
    for (int64_t w = 0; w < words_per_row_; ++w) {
      const uint64_t served = cells[w] | ShiftedWord(cells, w);
      unserved_samples_ += std::popcount(samples[w] & ~served);
    }
  }
}

void CellMask::RowBits(int64_t row, int64_t col0, int64_t count,
                       std::vector<uint64_t>* words) const {
  const auto out = static_cast<size_t>((count + 63) / 64);
  words->assign(std::max(out, words->size()), 0);
  if (row < 0 || row >= rows_) return;
  const uint64_t* source = bits_.data() + row * words_per_row_;
  // Cells at or past cols_ are clear in the mask, and the words past the
  // row's last are read as 0.
  const auto word_at = [&](int64_t w) {
    return w >= 0 && w < words_per_row_ ? source[w] : uint64_t{0};
  };
  for (size_t k = 0; k < out; ++k) {
    const int64_t start = col0 + static_cast<int64_t>(k) * 64;
    const int64_t w = start >= 0 ? start / 64 : -1;
    const int shift = static_cast<int>(start - w * 64);
    uint64_t bits = word_at(w) >> shift;
    if (shift != 0) bits |= word_at(w + 1) << (64 - shift);
    const int64_t left = count - static_cast<int64_t>(k) * 64;
    if (left < 64) bits &= (uint64_t{1} << left) - 1;
    (*words)[k] = bits;
  }
}

bool CellMask::AllValid(const GridRect& rect) const {
  if (valid_cells_ == static_cast<uint64_t>(cols_ * rows_)) return true;
  for (int64_t row = rect.row0; row < rect.row1; ++row) {
    for (int64_t col = rect.col0; col < rect.col1; ++col) {
      if (!Valid(col, row)) return false;
    }
  }
  return true;
}

namespace {

// The boundary of the valid cells inside a rectangle, as maximal straight
// runs between break vertices (corners and fixed points).
class BoundaryTracer {
 public:
  BoundaryTracer(const CellMask& mask, const GridRect& rect,
                 std::span<const GridPoint> fixed)
      : mask_(mask), rect_(rect), fixed_(fixed.begin(), fixed.end()) {
    std::sort(fixed_.begin(), fixed_.end(), [](const auto& a, const auto& b) {
      return std::pair(a.y, a.x) < std::pair(b.y, b.x);
    });
  }

  // Appends each run as a pair of point indices into *points.
  void Trace(std::vector<GridPoint>* points,
             std::vector<std::pair<size_t, size_t>>* runs);

 private:
  // Cell (col, row) is valid and inside the rectangle.
  bool In(int64_t col, int64_t row) const {
    return col >= rect_.col0 && col < rect_.col1 && row >= rect_.row0 &&
           row < rect_.row1 && mask_.Valid(col, row);
  }
  bool IsFixed(int64_t col, int64_t row) const {
    return std::binary_search(fixed_.begin(), fixed_.end(), GridPoint{col, row},
                              [](const auto& a, const auto& b) {
                                return std::pair(a.y, a.x) <
                                       std::pair(b.y, b.x);
                              });
  }
  // Bit c - col0 set for each cell (c, row) In() the rectangle.
  void CellRow(int64_t row, std::vector<uint64_t>* words) const;

  const CellMask& mask_;
  const GridRect rect_;
  std::vector<GridPoint> fixed_;
};

void BoundaryTracer::CellRow(int64_t row, std::vector<uint64_t>* words) const {
  if (row < rect_.row0 || row >= rect_.row1) {
    std::fill(words->begin(), words->end(), 0);
    return;
  }
  mask_.RowBits(row, rect_.col0, rect_.col1 - rect_.col0, words);
}

void BoundaryTracer::Trace(std::vector<GridPoint>* points,
                           std::vector<std::pair<size_t, size_t>>* runs) {
  // Vertex (col, row) has up to four boundary edges: horizontal ones left
  // and right (between the cells above and below them), vertical ones up
  // and down (between the cells left and right of them). It breaks a run
  // unless exactly two opposite ones are boundary and it is not fixed.
  const int64_t span = rect_.col1 - rect_.col0 + 1;  // vertex columns
  const size_t words = static_cast<size_t>((span + 64) / 64);
  std::vector<uint64_t> above(words), below(words);
  std::vector<int64_t> open_down(span, -1);  // a vertical run's first row
  std::vector<size_t> open_down_point(span);
  auto add_point = [&](int64_t col, int64_t row) {
    points->push_back(GridPoint{col, row});
    return points->size() - 1;
  };
  for (int64_t row = rect_.row0; row <= rect_.row1; ++row) {
    CellRow(row - 1, &above);
    CellRow(row, &below);
    size_t open_right_point = 0;
    bool open_right = false;
    for (size_t w = 0; w < words; ++w) {
      const uint64_t horizontal = above[w] ^ below[w];  // edge to the right
      const uint64_t horizontal_left =
          ShiftedWord(above, w) ^ ShiftedWord(below, w);
      const uint64_t up = above[w] ^ ShiftedWord(above, w);
      const uint64_t down = below[w] ^ ShiftedWord(below, w);
      uint64_t interesting = horizontal | horizontal_left | up | down;
      while (interesting != 0) {
        const int bit = std::countr_zero(interesting);
        interesting &= interesting - 1;
        const int64_t i = static_cast<int64_t>(w) * 64 + bit;
        if (i >= span) break;
        const int64_t col = rect_.col0 + i;
        const bool hl = (horizontal_left >> bit) & 1;
        const bool hr = (horizontal >> bit) & 1;
        const bool vu = (up >> bit) & 1;
        const bool vd = (down >> bit) & 1;
        const bool straight =
            (hl && hr && !vu && !vd) || (vu && vd && !hl && !hr);
        if (straight && !IsFixed(col, row)) continue;
        const size_t p = add_point(col, row);
        if (hl && open_right) runs->emplace_back(open_right_point, p);
        open_right = hr;
        open_right_point = p;
        if (vu && open_down[i] >= 0) runs->emplace_back(open_down_point[i], p);
        open_down[i] = vd ? row : -1;
        open_down_point[i] = p;
      }
    }
  }
}

}  // namespace

void TraceBoundary(const CellMask& mask, const GridRect& rect,
                   std::span<const GridPoint> fixed,
                   std::vector<GridPoint>* points,
                   std::vector<std::pair<size_t, size_t>>* runs) {
  BoundaryTracer(mask, rect, fixed).Trace(points, runs);
}

void BuildRegionMesh(const CellMask& mask, const GridRect& rect,
                     std::span<const GridPoint> fixed, TinMesh* mesh) {
  std::vector<GridPoint> points;
  std::vector<std::pair<size_t, size_t>> runs;
  TraceBoundary(mask, rect, fixed, &points, &runs);
  if (runs.empty()) return;

  std::vector<Cdt::Point> cgal_points;
  cgal_points.reserve(points.size());
  for (const GridPoint& p : points) {
    cgal_points.emplace_back(static_cast<double>(p.x),
                             static_cast<double>(p.y));
  }
  Cdt cdt;
  cdt.insert_constraints(cgal_points.begin(), cgal_points.end(), runs.begin(),
                         runs.end());

  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end();
       ++v) {
    v->info() = mesh->AddVertex(Point2{v->point().x(), v->point().y()});
  }
  // A face is in the domain when the cell holding a point of its interior
  // is: its boundary runs along constrained edges, so no face straddles it.
  // The centroid is interior; the cell to its lower right holds points of
  // the interior arbitrarily near it, whichever grid line it lies on.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    int64_t sum_x = 0, sum_y = 0;
    for (int i = 0; i < 3; ++i) {
      sum_x += static_cast<int64_t>(f->vertex(i)->point().x());
      sum_y += static_cast<int64_t>(f->vertex(i)->point().y());
    }
    // Grid coordinates are not negative: / rounds down.
    const int64_t col = sum_x / 3;
    const int64_t row = sum_y / 3;
    const bool in = col >= rect.col0 && col < rect.col1 && row >= rect.row0 &&
                    row < rect.row1 && mask.Valid(col, row);
    f->info() =
        in ? mesh->AddTriangle(f->vertex(0)->info(), f->vertex(1)->info(),
                               f->vertex(2)->info())
           : kOutside;
  }
  // CGAL's edge i is opposite vertex i: the half-edge from corner i + 1.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() == kOutside) continue;
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle n = f->neighbor(i);
      if (cdt.is_infinite(n) || n->info() == kOutside) continue;
      if (n->info() < f->info()) continue;  // linked from n
      const int j = n->index(f);
      mesh->Link(3 * f->info() + (i + 1) % 3, 3 * n->info() + (j + 1) % 3);
    }
  }
}

}  // namespace locator
