#include "server/core/terrain/grid/grid_refiner.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "server/core/mesh/prefetch.h"

namespace locator {

namespace {

// Insertions between two progress updates.
constexpr uint64_t kProgressEvery = 256;
// Rows of a triangle prefetched before it is scanned; taller ones are not.
constexpr int64_t kPrefetchRows = 16;
// Triangles a ScanAll thread takes at a time.
constexpr uint32_t kScanChunk = 1024;

}  // namespace

GridRefiner::GridRefiner(const ElevationGrid& grid, TinMesh* mesh,
                         GridMetric metric, const GridRegion& region,
                         double target)
    : grid_(grid),
      mesh_(mesh),
      metric_(metric),
      region_(region),
      has_cuts_(region.cut_left || region.cut_right || region.cut_top ||
                region.cut_bottom),
      target_(target) {}

double GridRefiner::MaxError() const {
  if (!queue_.empty()) return queue_.TopError();
  double largest = 0;
  for (size_t t = 0; t < error_.size(); ++t) {
    largest = std::max(largest, error_[t]);
  }
  return largest;
}

std::array<GridPoint, 3> GridRefiner::Corners(uint32_t t) const {
  std::array<GridPoint, 3> c;
  for (int i = 0; i < 3; ++i) {
    const Point2& p = mesh_->point(mesh_->Corner(t, i));
    c[i] = GridPoint{static_cast<int64_t>(p.x), static_cast<int64_t>(p.y)};
  }
  return c;
}

bool GridRefiner::OnCut(uint32_t t, int i) const {
  if (!has_cuts_ || mesh_->Twin(3 * t + i) != TinMesh::kNoTwin) return false;
  const Point2& p = mesh_->point(mesh_->Corner(t, i));
  const Point2& q = mesh_->point(mesh_->Corner(t, (i + 1) % 3));
  const GridRect& r = region_.rect;
  const auto along_x = [&](bool cut, int64_t col) {
    return cut && p.x == col && q.x == col;
  };
  const auto along_y = [&](bool cut, int64_t row) {
    return cut && p.y == row && q.y == row;
  };
  return along_x(region_.cut_left, r.col0) ||
         along_x(region_.cut_right, r.col1) ||
         along_y(region_.cut_top, r.row0) ||
         along_y(region_.cut_bottom, r.row1);
}

void GridRefiner::PrefetchRows(uint32_t t) const {
  const std::array<GridPoint, 3> c = Corners(t);
  const int64_t x_min = std::min({c[0].x, c[1].x, c[2].x});
  const int64_t x_max = std::max({c[0].x, c[1].x, c[2].x});
  const int64_t y_min = std::min({c[0].y, c[1].y, c[2].y});
  const int64_t y_max = std::max({c[0].y, c[1].y, c[2].y});
  if (y_max - y_min > kPrefetchRows) return;  // a large scan streams anyway
  const float* values = grid_.values.data();
  for (int64_t y = y_min; y <= y_max; ++y) {
    const float* row = values + static_cast<size_t>(y) * grid_.width;
    Prefetch(row + x_min);
    Prefetch(row + x_max);
  }
}

WorstSample GridRefiner::Measure(uint32_t t) const {
  const std::array<GridPoint, 3> c = Corners(t);
  if (metric_ == GridMetric::kServed) return WorstServedSample(grid_, c);
  return WorstPlaneSample(grid_, c, {OnCut(t, 0), OnCut(t, 1), OnCut(t, 2)});
}

void GridRefiner::Rescan(uint32_t t) {
  if (t >= candidate_.size()) {
    candidate_.resize(mesh_->num_triangles(), WorstSample::kNone);
    error_.resize(mesh_->num_triangles(), 0);
  }
  const WorstSample worst = Measure(t);
  candidate_[t] = worst.sample;
  error_[t] = worst.error;
  if (worst.error > target_) {
    queue_.Set(t, worst.error);
  } else {
    queue_.Remove(t);
  }
}

void GridRefiner::ScanAll(unsigned threads) {
  const auto triangles = static_cast<uint32_t>(mesh_->num_triangles());
  candidate_.resize(triangles, WorstSample::kNone);
  error_.resize(triangles, 0);
  std::atomic<uint32_t> next{0};
  const auto work = [&] {
    for (;;) {
      const uint32_t begin = next.fetch_add(kScanChunk);
      if (begin >= triangles) return;
      const uint32_t end = std::min(triangles, begin + kScanChunk);
      for (uint32_t t = begin; t < end; ++t) {
        const WorstSample worst = Measure(t);
        candidate_[t] = worst.sample;
        error_[t] = worst.error;
      }
    }
  };
  std::vector<std::thread> helpers;
  const unsigned extra =
      std::min<unsigned>(threads > 0 ? threads - 1 : 0, triangles / kScanChunk);
  for (unsigned i = 0; i < extra; ++i) helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers) helper.join();
  queue_.Clear();
  for (uint32_t t = 0; t < triangles; ++t) {
    if (error_[t] > target_) queue_.Push(t, error_[t]);
  }
}

Status GridRefiner::Refine(uint64_t max_vertices, TinProgressReporter* progress,
                           size_t slot) {
  uint64_t inserted = 0;
  while (!queue_.empty() &&
         (max_vertices == 0 || mesh_->num_vertices() < max_vertices)) {
    const uint32_t t = queue_.Pop();
    const uint64_t sample = candidate_[t];
    const Point2 p{static_cast<double>(sample % grid_.width),
                   static_cast<double>(sample / grid_.width)};
    const uint32_t v = mesh_->AddVertex(p);
    if (!mesh_->Insert(v, t)) {
      return Status::Internal("greedy insertion: sample (" +
                              std::to_string(sample % grid_.width) + ", " +
                              std::to_string(sample / grid_.width) +
                              ") is not inside its triangle");
    }
    // The scans miss the cache on every row: ask for all the rows first,
    // so that the misses overlap.
    for (const uint32_t u : mesh_->touched()) PrefetchRows(u);
    for (const uint32_t u : mesh_->touched()) Rescan(u);
    if (++inserted % kProgressEvery == 0 && progress != nullptr) {
      progress->Update(slot, mesh_->num_vertices(), queue_.TopError());
    }
  }
  if (progress != nullptr) {
    progress->Update(slot, mesh_->num_vertices(), MaxError());
  }
  return Status::OK();
}

}  // namespace locator
