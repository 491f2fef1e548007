#include "server/core/tuning/hot_region_tuner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "server/core/geometry/wide_math.h"

namespace locator {

namespace {

// Starts per vertex a cell may have: about 2 per triangle, so that a
// query's sub-cell is mostly smaller than its triangle and the walk often
// starts in it (1.42 faces per query on a hot spot at n = 10^6, against
// 1.70 at 1.5 per vertex). Deeper cells buy little more and make the
// re-tunes that follow a moving hot spot build more (at 6 per vertex, 1.34
// faces, but drift's tuner share rose from 0.54 to 0.67).
constexpr double kStartsPerPointCap = 4;
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

std::vector<uint32_t> HotRegionTuner::PlanLevels(
    const std::vector<double>& weight) const {
  const size_t cells = grid_.cells();
  std::vector<double> desire(cells), cap(cells), starts(cells, 0.0);
  double weight_factor = 0;
  for (size_t c = 0; c < cells; ++c) {
    // (w * sqrt(P))^(2/3); cells without traffic share one weight.
    if (c == 0 || weight[c] != weight[c - 1]) {
      weight_factor = std::cbrt(weight[c] * weight[c]);
    }
    desire[c] = weight_factor * cbrt_points_[c];
    cap[c] = kStartsPerPointCap * points_[c] + 1;
  }
  // Water-filling: scale desires to the budget, pin the cells that hit
  // their cap, and share what they leave among the rest.
  std::vector<char> pinned(cells, 0);
  double remaining = kPlanFill * static_cast<double>(leaf_budget_);
  for (int round = 0; round < 16; ++round) {
    double open = 0;
    for (size_t c = 0; c < cells; ++c) open += pinned[c] ? 0 : desire[c];
    if (open <= 0 || remaining <= 0) break;
    const double scale = remaining / open;
    bool pinned_any = false;
    for (size_t c = 0; c < cells; ++c) {
      if (!pinned[c] && scale * desire[c] >= cap[c]) {
        pinned[c] = 1;
        starts[c] = cap[c];
        remaining -= cap[c];
        pinned_any = true;
      }
    }
    if (!pinned_any) {
      for (size_t c = 0; c < cells; ++c) {
        if (!pinned[c]) starts[c] = scale * desire[c];
      }
      break;
    }
  }
  std::vector<uint32_t> levels(cells);
  for (size_t c = 0; c < cells; ++c) {
    levels[c] = std::max<uint32_t>(
        1, static_cast<uint32_t>(std::sqrt(std::max(0.0, starts[c]))));
  }
  return levels;
}

std::vector<char> HotRegionTuner::SignificantChanges(
    const std::vector<double>& reference, double total) const {
  std::vector<char> significant(counts_.size(), 1);
  if (!table_) return significant;
  for (size_t c = 0; c < counts_.size(); ++c) {
    const double expected = reference[c] * total;
    // |count - expected| > kSignificance * sqrt(expected + 1), squared.
    const double departure = counts_[c] - expected;
    significant[c] =
        departure * departure > kSignificance * kSignificance * (expected + 1);
  }
  return significant;
}

double HotRegionTuner::CellLeaves(size_t c, uint32_t r) const {
  const size_t n = ShapeOf(c, r).cells();
  return n > 1 ? static_cast<double>(n) : 0;
}

double HotRegionTuner::Leaves(const std::vector<uint32_t>& levels) const {
  double sum = 0;
  for (size_t c = 0; c < levels.size(); ++c) sum += CellLeaves(c, levels[c]);
  return sum;
}

std::vector<uint32_t> HotRegionTuner::KeepStableCells(
    std::vector<uint32_t> fresh, const std::vector<char>& significant) const {
  if (!table_) return fresh;
  // Keep cells whose traffic did not change, or whose new level is
  // within hysteresis; and, while the budget allows, cells that would only
  // shrink: their starts are already paid for, and traffic may come back.
  std::vector<uint32_t> mixed(fresh.size());
  std::vector<char> stable(fresh.size());
  for (bool keep_shrinking : {true, false}) {
    for (size_t c = 0; c < fresh.size(); ++c) {
      const uint32_t old_r = levels_[c];
      stable[c] = !significant[c] ||
                  (fresh[c] <= kHysteresis * old_r &&
                   fresh[c] * kHysteresis >= old_r) ||
                  (keep_shrinking && fresh[c] < old_r);
      mixed[c] = stable[c] ? old_r : fresh[c];
    }
    if (Leaves(mixed) <= static_cast<double>(leaf_budget_)) return mixed;
  }
  // The cells that change get what the stable ones leave, in the fresh
  // plan's proportions (levels scale with the square root of the starts),
  // so that a re-tune rebuilds only the cells whose traffic changed.
  double kept = 0, wanted = 0;
  for (size_t c = 0; c < fresh.size(); ++c) {
    // A cell that must shrink means the traffic left it: the hot spot
    // moved, and the fresh plan is the one to build.
    if (!stable[c] && fresh[c] < levels_[c]) return fresh;
    (stable[c] ? kept : wanted) += CellLeaves(c, mixed[c]);
  }
  const double left = static_cast<double>(leaf_budget_) - kept;
  if (left > 0 && wanted > 0) {
    const double scale = std::sqrt(kPlanFill * left / wanted);
    for (size_t c = 0; c < fresh.size(); ++c) {
      if (stable[c]) continue;
      mixed[c] = std::max<uint32_t>(
          1, static_cast<uint32_t>(scale * static_cast<double>(fresh[c])));
    }
    if (Leaves(mixed) <= static_cast<double>(leaf_budget_)) return mixed;
  }
  return fresh;
}

double HotRegionTuner::Walks(const std::vector<uint32_t>& levels) const {
  double walks = 0;
  for (size_t c = 0; c < levels.size(); ++c) {
    if (levels[c] != levels_[c]) {
      walks += static_cast<double>(ShapeOf(c, levels[c]).cells());
    }
  }
  return walks;
}

std::vector<uint32_t> HotRegionTuner::FitWork(
    const std::vector<double>& weight, const std::vector<uint32_t>& fresh) {
  if (Walks(fresh) <= work_credit_) return fresh;
  // From the current levels, grow the cells that save the most walk per
  // start walked while the credit lasts. A cell the plan shrinks keeps its
  // starts (paid for already) until a growth needs its memory: then the
  // coldest such cells shrink first.
  struct Change {
    size_t cell;
    double walks;
    double order;  // growths: walk saved per start walked; shrinks: weight
  };
  std::vector<Change> growths, shrinks;
  for (size_t c = 0; c < fresh.size(); ++c) {
    if (fresh[c] == levels_[c]) continue;
    const auto walks = static_cast<double>(ShapeOf(c, fresh[c]).cells());
    if (fresh[c] < levels_[c]) {
      shrinks.push_back({c, walks, weight[c]});
    } else {
      const double gain = weight[c] * (walk_terms_[c] - WalkTerm(c, fresh[c]));
      growths.push_back({c, walks, gain / walks});
    }
  }
  std::sort(growths.begin(), growths.end(),
            [](const Change& a, const Change& b) { return a.order > b.order; });
  std::sort(shrinks.begin(), shrinks.end(),
            [](const Change& a, const Change& b) { return a.order < b.order; });
  std::vector<uint32_t> plan = levels_;
  double leaves = Leaves(levels_);
  const auto budget = static_cast<double>(leaf_budget_);
  double credit = work_credit_;
  size_t next_shrink = 0;
  for (const Change& g : growths) {
    const double more =
        CellLeaves(g.cell, fresh[g.cell]) - CellLeaves(g.cell, levels_[g.cell]);
    while (leaves + more > budget && next_shrink < shrinks.size()) {
      const Change& s = shrinks[next_shrink++];
      plan[s.cell] = fresh[s.cell];
      leaves -= CellLeaves(s.cell, levels_[s.cell]) -
                CellLeaves(s.cell, fresh[s.cell]);
      credit -= s.walks;
    }
    if (g.walks > credit || leaves + more > budget) {
      deferred_walks_ = std::min(deferred_walks_, g.walks);
      continue;
    }
    plan[g.cell] = fresh[g.cell];
    leaves += more;
    credit -= g.walks;
  }
  return plan;
}

double HotRegionTuner::ExpectedWalk(const std::vector<double>& weight,
                                    const std::vector<uint32_t>& levels) const {
  double walk = 0;
  for (size_t c = 0; c < weight.size(); ++c) {
    const bool current = c < levels_.size() && levels[c] == levels_[c];
    walk += weight[c] * (current ? walk_terms_[c] : WalkTerm(c, levels[c]));
  }
  return walk;
}

double HotRegionTuner::SignificantWalk(
    const std::vector<double>& weight,
    const std::vector<char>& significant) const {
  double walk = 0;
  for (size_t c = 0; c < weight.size(); ++c) {
    walk += significant[c] ? weight[c] * walk_terms_[c] : 0.0;
  }
  return walk;
}

double HotRegionTuner::WalkTerm(size_t c, uint32_t r) const {
  // The distortion of a shape is (q * rows + columns) / (2 * sqrt(q * S)).
  const SubGrid shape = ShapeOf(c, r);
  const double q = crossing_ratio_[c];
  const double starts = static_cast<double>(shape.cells());
  const double distortion =
      (q * shape.rows + shape.columns) / (2 * std::sqrt(q * starts));
  return std::sqrt(points_[c] / starts) * distortion;
}

void HotRegionTuner::SetCurrentLevels(std::vector<uint32_t> levels) {
  levels_ = std::move(levels);
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

bool HotRegionTuner::Plan() {
  const double total = std::accumulate(counts_.begin(), counts_.end(), 0.0);
  if (total == 0 && options_.mesh_larger_than_memory) return false;
  MeasureCells();
  builder_.reset();
  const size_t cells = grid_.cells();
  const double prior =
      options_.mesh_larger_than_memory ? 0.0 : (total > 0 ? kPriorShare : 1.0);
  const std::vector<double> share = Shares(total);
  std::vector<double> weight(cells);
  for (size_t c = 0; c < cells; ++c) {
    weight[c] = prior / cells + (1 - prior) * (total > 0 ? share[c] : 0.0);
  }
  // Traffic that moved within noise keeps the table without planning, and
  // so does a change confined to cells that carry less than kMinGain of
  // the expected walk: no new plan for them could gain that much. Both
  // against the table's plan and against the last planning that kept it,
  // unless the credit now pays for a growth that planning deferred.
  const std::vector<char> significant =
      SignificantChanges(planned_share_, total);
  if (table_) {
    const double walk = ExpectedWalk(weight, levels_);
    if (SignificantWalk(weight, significant) <= kMinGain * walk) return false;
    if (work_credit_ < deferred_walks_ &&
        SignificantWalk(weight, SignificantChanges(considered_share_, total)) <=
            kMinGain * walk) {
      return false;
    }
  }
  considered_share_ = share;
  deferred_walks_ = HUGE_VAL;
  const std::vector<uint32_t> fresh =
      KeepStableCells(PlanLevels(weight), significant);
  std::vector<uint32_t> plan = fresh;
  std::vector<double> planned_share = share;
  if (table_) {
    if (ExpectedWalk(weight, fresh) >
        (1 - kMinGain) * ExpectedWalk(weight, levels_)) {
      return false;
    }
    plan = FitWork(weight, fresh);
    if (plan == levels_) return false;
    work_credit_ -= Walks(plan);
    // A cell left below its plan keeps the share it was planned for, so
    // that it stays a significant change until a re-tune grows it.
    for (size_t c = 0; c < cells; ++c) {
      if (plan[c] != fresh[c]) planned_share[c] = planned_share_[c];
    }
  }
  builder_ = std::make_unique<StartTable::Builder>(mesh_, grid_, Shapes(plan),
                                                   table_.get());
  building_levels_ = std::move(plan);
  building_share_ = std::move(planned_share);
  return true;
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
