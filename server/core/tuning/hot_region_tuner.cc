#include "server/core/tuning/hot_region_tuner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "server/core/geometry/wide_math.h"

namespace locator {

namespace {

// Crossing ratios are clamped to [1 / kMaxCrossingRatio, kMaxCrossingRatio]:
// a cell whose edges all run one way has no meaningful ratio.
constexpr double kMaxCrossingRatio = 1e4;
// With TuningOptions::mesh_larger_than_memory, a mesh of more faces than
// this is measured on blocks of kMeasuredBlockFaces consecutive faces, this
// many faces in all (about 200 MB of a mesh file read, however large).
constexpr uint32_t kMaxMeasuredFaces = uint32_t{1} << 23;
constexpr uint32_t kMeasuredBlockFaces = 4096;

}  // namespace

HotRegionTuner::HotRegionTuner(const ServingMesh& mesh,
                               const GridGeometry& grid,
                               const TuningOptions& options, size_t fixed_bytes)
    : mesh_(mesh),
      grid_(grid),
      options_(options),
      counts_(grid.cells(), 0.0),
      points_(grid.cells(), 0.0),
      crossing_ratio_(grid.cells(), 1.0),
      planned_share_(grid.cells(), 1.0 / grid.cells()),
      considered_share_(planned_share_) {
  budget_ = Budget(mesh, options);
  // The owner's histogram, our per-cell arrays, the snapshot's histogram
  // copy and hot flags, and the coarse table are paid first; what is left
  // buys sub-grid starts.
  const size_t fixed = fixed_bytes +
                       grid.cells() * (5 * sizeof(double) + sizeof(char)) +
                       grid.cells() * StartTable::kBytesPerCell;
  leaf_budget_ =
      budget_ > fixed ? (budget_ - fixed) / StartTable::kBytesPerStart : 0;
}

void HotRegionTuner::MeasureCells() {
  if (cells_measured_) return;
  cells_measured_ = true;
  // A segment of length L along x crosses about L * sum|dy| / area edges
  // (and along y, L * sum|dx| / area), summing over the edges around it.
  // The sums are in Wide: an edge of a dataset spanning +-1e308 is longer
  // than a double, and so may be a sum of many short ones.
  const size_t cells = grid_.cells();
  std::vector<Wide> sum_dx(cells, 0), sum_dy(cells, 0);
  Wide all_dx = 0, all_dy = 0;
  const auto measure_edges = [&](uint32_t first, uint32_t end) {
    // Each edge once: from the face with the smaller index, or the hull
    // side.
    for (uint32_t f = first; f < end; ++f) {
      for (int i = 0; i < 3; ++i) {
        const uint32_t n = mesh_.Neighbor(f, i);
        if (!ServingMesh::IsHull(n) && n < f) continue;
        const Point2& a = mesh_.CornerPoint(f, Ccw(i));
        const Point2& b = mesh_.CornerPoint(f, Cw(i));
        const size_t c = grid_.CellOf(Midpoint(a, b));
        const Wide dx = std::abs(Wide{a.x} - b.x);
        const Wide dy = std::abs(Wide{a.y} - b.y);
        sum_dx[c] += dx;
        sum_dy[c] += dy;
        all_dx += dx;
        all_dy += dy;
      }
    }
  };
  const uint32_t faces = mesh_.num_faces();
  if (!options_.mesh_larger_than_memory || faces <= kMaxMeasuredFaces) {
    for (const Point2& p : mesh_.arrays().points) {
      points_[grid_.CellOf(p)] += 1;
    }
    measure_edges(0, faces);
  } else {
    // Evenly spaced blocks of consecutive faces (compact regions: faces
    // follow a Hilbert curve), each face standing for `scale` faces, and a
    // mesh has about half as many vertices as faces.
    constexpr uint32_t kBlocks = kMaxMeasuredFaces / kMeasuredBlockFaces;
    const double scale =
        static_cast<double>(faces) / (double{kBlocks} * kMeasuredBlockFaces);
    for (uint32_t b = 0; b < kBlocks; ++b) {
      const uint32_t first =
          static_cast<uint32_t>(uint64_t{b} * faces / kBlocks);
      const uint32_t end = std::min(first + kMeasuredBlockFaces, faces);
      for (uint32_t f = first; f < end; ++f) {
        // Its first corner's cell: the face's vertices share its cell
        // but for a few along the cell borders.
        points_[grid_.CellOf(mesh_.CornerPoint(f, 0))] += scale / 2;
      }
      measure_edges(first, end);
    }
  }
  cbrt_points_.resize(points_.size());
  for (size_t c = 0; c < points_.size(); ++c) {
    cbrt_points_[c] = std::cbrt(points_[c]);
  }
  const Wide aspect = grid_.CellAspect();
  for (size_t c = 0; c < cells; ++c) {
    // Cells without edges of both directions take the dataset's ratio.
    const bool own = sum_dx[c] > 0 && sum_dy[c] > 0;
    const Wide dx = own ? sum_dx[c] : all_dx;
    const Wide dy = own ? sum_dy[c] : all_dy;
    crossing_ratio_[c] =
        dx > 0 && dy > 0 ? static_cast<double>(std::clamp(
                               aspect * dy / dx, 1 / Wide{kMaxCrossingRatio},
                               Wide{kMaxCrossingRatio}))
                         : 1.0;
  }
}

SubGrid HotRegionTuner::ShapeOf(size_t c, uint32_t r) const {
  if (c < current_shapes_.size() && r == levels_[c]) return current_shapes_[c];
  return NewShape(c, r);
}

SubGrid HotRegionTuner::NewShape(size_t c, uint32_t r) const {
  if (r <= 1) return SubGrid{};
  // Minimising q / columns + 1 / rows (the crossings of a walk within a
  // sub-cell, in units of the cell's height) at columns * rows = r * r gives
  // columns / rows = q.
  // Every re-tune shapes every cell a few times: round by conversion, not
  // by a libm call (the values are positive and below 2^64).
  const auto round = [](double x) {
    return static_cast<double>(static_cast<uint64_t>(x + 0.5));
  };
  const double starts = static_cast<double>(r) * r;
  const double columns =
      std::clamp(round(std::sqrt(starts * crossing_ratio_[c])), 1.0, starts);
  const double rows = std::max(1.0, round(starts / columns));
  return SubGrid{static_cast<uint32_t>(columns), static_cast<uint32_t>(rows)};
}

std::vector<SubGrid> HotRegionTuner::Shapes(
    const std::vector<uint32_t>& levels) const {
  std::vector<SubGrid> shapes(levels.size());
  for (size_t c = 0; c < levels.size(); ++c) shapes[c] = ShapeOf(c, levels[c]);
  return shapes;
}

size_t HotRegionTuner::Budget(const ServingMesh& mesh,
                              const TuningOptions& options) {
  return options.budget_bytes > 0
             ? options.budget_bytes
             : static_cast<size_t>(options.budget_fraction *
                                   static_cast<double>(mesh.MemoryBytes()));
}

int HotRegionTuner::CoarseGridSize(size_t budget, int max_grid) {
  int g = max_grid;
  while (g > 4 && size_t(g) * g * kBytesPerCoarseCell > budget / 4) --g;
  return g;
}

void HotRegionTuner::AddCounts(const std::vector<double>& fresh) {
  const double keep = seen_traffic_ ? options_.decay : 0.0;
  double queries = 0;
  for (size_t c = 0; c < counts_.size(); ++c) {
    counts_[c] = counts_[c] * keep + fresh[c];
    queries += fresh[c];
  }
  work_credit_ = std::min(work_credit_ + kWorkPerQuery * queries, kWorkBurst);
  seen_traffic_ = seen_traffic_ || std::any_of(fresh.begin(), fresh.end(),
                                               [](double x) { return x > 0; });
}

void HotRegionTuner::SetCurrentLevels(std::vector<uint32_t> levels) {
  levels_ = std::move(levels);
  current_shapes_.resize(levels_.size());
  for (size_t c = 0; c < levels_.size(); ++c) {
    current_shapes_[c] = NewShape(c, levels_[c]);
  }
  walk_terms_.resize(levels_.size());
  for (size_t c = 0; c < levels_.size(); ++c) {
    walk_terms_[c] = WalkTerm(c, levels_[c]);
  }
}

std::vector<double> HotRegionTuner::Shares(double total) const {
  std::vector<double> share(counts_.size(), 1.0 / counts_.size());
  if (total > 0) {
    for (size_t c = 0; c < counts_.size(); ++c) share[c] = counts_[c] / total;
  }
  return share;
}

std::shared_ptr<const TuningSnapshot> HotRegionTuner::Snapshot(
    uint64_t version) const {
  return SnapshotOf(table_, version);
}

std::shared_ptr<const TuningSnapshot> HotRegionTuner::CoarseSnapshot(
    uint64_t version) const {
  return SnapshotOf(std::make_shared<const StartTable>(
                        mesh_, grid_, std::vector<SubGrid>(grid_.cells())),
                    version);
}

std::shared_ptr<const TuningSnapshot> HotRegionTuner::SnapshotOf(
    std::shared_ptr<const StartTable> table, uint64_t version) const {
  const size_t cells = grid_.cells();
  const double total = std::accumulate(counts_.begin(), counts_.end(), 0.0);
  const std::vector<double> share = Shares(total);
  auto snapshot = std::make_shared<TuningSnapshot>();
  snapshot->version = version;
  snapshot->hot.assign(cells, 1);
  if (total > 0) {
    for (size_t c = 0; c < cells; ++c)
      snapshot->hot[c] = share[c] * cells >= 0.5;
  }
  snapshot->table = std::move(table);
  snapshot->histogram = counts_;
  snapshot->memory_bytes = snapshot->table->MemoryBytes() +
                           snapshot->hot.capacity() +
                           snapshot->histogram.capacity() * sizeof(double) +
                           4 * cells * sizeof(double);  // the tuner's arrays
  return snapshot;
}

bool HotRegionTuner::BuildStep(size_t max_units, size_t* units) {
  if (!builder_ || !builder_->Step(max_units, units)) return !builder_;
  table_ = builder_->Finish();
  builder_.reset();
  SetCurrentLevels(std::move(building_levels_));
  planned_share_ = std::move(building_share_);
  return true;
}

std::shared_ptr<const TuningSnapshot> HotRegionTuner::Build(uint64_t version) {
  Plan();
  size_t units = 0;
  BuildStep(SIZE_MAX, &units);
  // Nothing planned yet (a mesh larger than memory, no traffic): coarse.
  return table_ != nullptr ? Snapshot(version) : CoarseSnapshot(version);
}

TuningFingerprint HotRegionTuner::Fingerprint(std::string_view strategy) const {
  TuningFingerprint fingerprint;
  fingerprint.dataset_digest = mesh_.digest();
  fingerprint.input_points = mesh_.id_bound();
  fingerprint.strategy = std::string(strategy);
  fingerprint.grid_size = static_cast<uint32_t>(grid_.size());
  fingerprint.grid_box = grid_.box();
  fingerprint.budget_bytes = budget_;
  return fingerprint;
}

void HotRegionTuner::ExportState(TuningState* state) const {
  state->seen_traffic = seen_traffic_;
  state->histogram = counts_;
  state->planned_share = planned_share_;
  state->levels = levels_;
  const std::vector<StartTable::Face> faces = table_->Starts();
  state->starts.resize(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    state->starts[i] = faces[i] == StartTable::kUnresolved
                           ? kUnresolvedStart
                           : mesh_.CornerIds(faces[i]);
  }
}

Status HotRegionTuner::Restore(
    const TuningState& state, uint64_t version,
    std::shared_ptr<const TuningSnapshot>* snapshot) {
  MeasureCells();
  const size_t cells = grid_.cells();
  if (state.histogram.size() != cells || state.planned_share.size() != cells ||
      state.levels.size() != cells) {
    return Status::InvalidArgument(
        "tuning state sized for " + std::to_string(state.levels.size()) +
        " cells, the grid has " + std::to_string(cells));
  }
  for (uint32_t r : state.levels) {
    if (r < 1 || r > kMaxStoredLevel) {
      return Status::InvalidArgument("tuning state sub-grid level " +
                                     std::to_string(r));
    }
  }
  const std::vector<SubGrid> shapes = Shapes(state.levels);
  uint64_t implied = 0;
  for (const SubGrid& shape : shapes) implied += shape.cells();
  if (state.starts.size() != implied) {
    return Status::InvalidArgument(
        "tuning state has " + std::to_string(state.starts.size()) +
        " starts, its levels need " + std::to_string(implied));
  }
  std::vector<StartTable::Face> faces = mesh_.FacesWithCorners(state.starts);
  size_t i = 0;
  for (const SubGrid& shape : shapes) {
    for (size_t k = 0; k < shape.cells(); ++k, ++i) {
      // An unrefined cell may wait for its first use (kUnresolvedStart).
      if (shape.cells() == 1 && state.starts[i] == kUnresolvedStart) {
        faces[i] = StartTable::kUnresolved;
      } else if (faces[i] == ServingMesh::kNoFace) {
        const auto& ids = state.starts[i];
        return Status::InvalidArgument(
            "tuning state start " + std::to_string(i) + ": vertices " +
            std::to_string(ids[0]) + ", " + std::to_string(ids[1]) + ", " +
            std::to_string(ids[2]) + " are not a triangle of this dataset");
      }
    }
  }
  builder_.reset();  // it may borrow the table replaced here
  table_ = std::make_shared<StartTable>(mesh_, grid_, shapes, faces);
  SetCurrentLevels(state.levels);
  counts_ = state.histogram;
  planned_share_ = state.planned_share;
  seen_traffic_ = state.seen_traffic;
  *snapshot = Snapshot(version);
  return Status::OK();
}

}  // namespace locator
