// HotRegionTuner: decides where the self-tuning strategy spends its start
// points, and builds the immutable snapshot the read path uses.
//
// It owns the long-term query histogram (decayed at every re-tune, so old
// traffic fades and a moved hot spot is re-learned), the number of
// triangulation vertices in each coarse cell and each cell's crossing ratio:
// how many more edges a walk crosses per unit of width than per unit of
// height there (1 for round triangles in a square cell, 1/50 for a mesh
// stretched 50:1 along x). From these it plans a sub-grid level r per coarse
// cell under a memory budget: with w the cell's share of traffic and P its
// points, a cell with S starts costs about w * sqrt(P / S) faces per query,
// and minimising the sum under sum S = L gives S proportional to
// (w * sqrt(P))^(2/3). A level r buys about r * r starts, laid out as a
// columns x rows sub-grid shaped by the crossing ratio, so that a walk from
// a sub-cell's centre crosses as many edges along x as along y: on a
// stretched mesh the sub-cells are stretched alike, and the square-cell cost
// above holds. Starts are capped near the cell's point count, beyond which
// the walk cannot get shorter. A small prior share of uniform traffic keeps
// every cell served, so under uniform traffic the plan is a coarse uniform
// grid and no traffic is ever answered worse than by a start in its own cell.
//
// Re-tunes are incremental: a cell keeps its level unless its count
// departs from the share the current table was planned for by more than
// kSignificance standard deviations (Poisson) and the new plan differs by
// more than kHysteresis (noise in the histogram must not cost a rebuild);
// the table is rebuilt only if the cost model predicts at least
// kMinGain fewer faces per query than the current table, otherwise it is
// reused outright (without planning, when the cells whose traffic changed
// carry less than kMinGain of the expected walk); cells shrink only when the
// budget needs their starts; and a rebuild shares every unchanged cell. A
// rebuild can run in bounded steps (Plan(), then BuildStep() until it returns
// true) while the old table serves; the new plan becomes current only when its
// table is complete. The plan fills kPlanFill of the budget so that kept cells
// have headroom. When the kept cells leave too little and every cell that
// changes grows, those are scaled down to what is left (a hot spot appearing
// rebuilds its own cells, not the whole table); a cell that must shrink (the
// hot spot moved), or a mix that still exceeds the budget, falls back to the
// fresh plan.
//
// Re-tunes pay for themselves: building a start is a walk, about the cost
// of a query, so the walks of all re-tunes are held to kWorkPerQuery per
// query counted, from a credit that saves up to kWorkBurst of them. A plan
// that would walk more than the credit grows only the cells that save the
// most walk per start walked, as far as the credit goes, and shrinks cells
// only for the memory those growths need; the next re-tunes grow the others
// as the traffic stays. A stable hot spot is so learned
// within a few re-tunes, one that moves every few thousand queries (drift)
// is refined only as far as its queries pay for, and the tuner's share of
// the CPU stays near kWorkPerQuery under any traffic. The first table is
// not a re-tune and is built whole.
//
// Thread-safety: not thread-safe; the owner serialises calls.

#ifndef LOCATOR_CORE_HOT_REGION_TUNER_H_
#define LOCATOR_CORE_HOT_REGION_TUNER_H_

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "locator/tuning_options.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tuning/query_histogram.h"
#include "server/core/tuning/start_table.h"
#include "server/core/tuning/tuning_state.h"

namespace locator {

// What the read path uses between two re-tunes. Immutable once published.
struct TuningSnapshot {
  uint64_t version = 0;
  std::shared_ptr<const StartTable> table;  // shared while the plan holds
  // hot[c]: coarse cell c drew at least half a uniform share of the traffic
  // this snapshot was tuned for. Queries elsewhere count as "cold hits"; a
  // burst of them means the traffic moved.
  std::vector<char> hot;
  std::vector<double> histogram;  // decayed counts it was tuned from
  size_t memory_bytes = 0;
};

class HotRegionTuner {
 public:
  // Share of the plan reserved for uniform traffic.
  static constexpr double kPriorShare = 0.1;
  static constexpr double kHysteresis = 1.5;
  static constexpr double kPlanFill = 0.9;
  static constexpr double kMinGain = 0.05;
  static constexpr double kSignificance = 3.0;
  // Start walks a re-tune may spend per query counted, and the most the
  // credit saves up. At 0.25 the tuner took 11-15 % of the CPU on d-cluster
  // and x-cluster (re-tunes that learn the band at the credit's pace) for
  // walks 0.01 faces shorter than at 0.1.
  static constexpr double kWorkPerQuery = 0.1;
  static constexpr double kWorkBurst = 65536;
  // Bookkeeping per coarse cell: histogram shards (counts and what was
  // drained), our counts, point counts and their cube roots, the current
  // table's walk terms, the snapshot's histogram copy and hot flag, the
  // table's cell.
  static constexpr size_t kBytesPerCoarseCell =
      2 * QueryHistogram::kShards * sizeof(uint32_t) + 5 * sizeof(double) + 1 +
      StartTable::kBytesPerCell;

  // The memory budget for `mesh` under `options`, in bytes.
  static size_t Budget(const ServingMesh& mesh, const TuningOptions& options);
  // The largest coarse grid <= max_grid whose bookkeeping takes at most a
  // quarter of `budget` (at least 4): a tiny budget buys starts, not cells.
  static int CoarseGridSize(size_t budget, int max_grid);

  // `mesh` must outlive the tuner. `fixed_bytes` is the memory the owner spends
  // outside the snapshot's table (counted against the budget).
  HotRegionTuner(const ServingMesh& mesh, const GridGeometry& grid,
                 const TuningOptions& options, size_t fixed_bytes);

  // Folds the counts since the last call into the decayed histogram.
  void AddCounts(const std::vector<double>& fresh);
  // Plans the next table from the histogram, abandoning any build in
  // progress; true if the plan needs a new table, which BuildStep() builds.
  bool Plan();
  // Does at most max_units (>= 1) units of the pending build (see
  // StartTable::Builder) and adds their number to *units; true once nothing
  // is pending (the planned table is then current).
  bool BuildStep(size_t max_units, size_t* units);
  bool building() const { return builder_ != nullptr; }
  // Plan() and BuildStep() to completion; then Snapshot(version), or
  // CoarseSnapshot(version) while nothing was ever planned.
  std::shared_ptr<const TuningSnapshot> Build(uint64_t version);
  // The snapshot of the current table and histogram, as `version`.
  std::shared_ptr<const TuningSnapshot> Snapshot(uint64_t version) const;
  // A snapshot, as `version`, of a table with one start per coarse cell and
  // no sub-grids, each found on its first use: nothing is walked to make
  // it. The tuner's own table stays as it was (none before the first
  // Build()).
  std::shared_ptr<const TuningSnapshot> CoarseSnapshot(uint64_t version) const;

  // What a state learned by this tuner means: the dataset, `strategy`, the
  // grid and the budget.
  TuningFingerprint Fingerprint(std::string_view strategy) const;
  // Fills the learned parts of *state (histogram, plan, starts by vertex
  // id); the owner fills the version and re-tune count.
  void ExportState(TuningState* state) const;
  // Takes over `state` (exported by a tuner with the same fingerprint) and
  // sets *snapshot to the snapshot it was tuned to, as `version`.
  // InvalidArgument, leaving the tuner unchanged, if a size disagrees with
  // the grid or a start's ids name no triangle of this dataset.
  Status Restore(const TuningState& state, uint64_t version,
                 std::shared_ptr<const TuningSnapshot>* snapshot);

  size_t budget_bytes() const { return budget_; }

 private:
  // counts_ as shares of their total (uniform when there is no traffic).
  std::vector<double> Shares(double total) const;
  std::vector<uint32_t> PlanLevels(const std::vector<double>& weight) const;
  // significant[c]: cell c's count departs from its share in `reference`
  // (of the traffic the table was planned for, or last planned from) by
  // more than Poisson noise (all, without a table).
  std::vector<char> SignificantChanges(const std::vector<double>& reference,
                                       double total) const;
  // Sub-grid starts (beyond the coarse cell's own) that level r places in
  // cell c, and that `levels` place in all cells.
  double CellLeaves(size_t c, uint32_t r) const;
  double Leaves(const std::vector<uint32_t>& levels) const;
  // The fresh plan, except for cells without a significant change, whose
  // new level is within hysteresis of the current one, or (while the
  // budget allows) that would only shrink. When keeping them leaves too
  // little budget for the fresh plan's other cells and those all grow, they
  // are scaled down to fit; otherwise the fresh plan is used whole.
  std::vector<uint32_t> KeepStableCells(
      std::vector<uint32_t> fresh, const std::vector<char>& significant) const;
  // The starts that building `levels` walks for: those of every cell whose
  // sub-grid changes (an unchanged cell is copied).
  double Walks(const std::vector<uint32_t>& levels) const;
  // `fresh` if its walks fit work_credit_. Else the current levels with,
  // of fresh's growing cells, those that save the most walk under `weight`
  // per start walked while the credit lasts, and of its shrinking cells the
  // coldest, as far as those growths need their memory. The fewest walks a
  // deferred growth needs is noted in deferred_walks_.
  std::vector<uint32_t> FitWork(const std::vector<double>& weight,
                                const std::vector<uint32_t>& fresh);
  // The model's expected walk length (up to a constant) under `weight` for
  // per-cell levels `levels`: the sum of weight[c] * WalkTerm(c, levels[c]),
  // with the current table's terms from walk_terms_.
  double ExpectedWalk(const std::vector<double>& weight,
                      const std::vector<uint32_t>& levels) const;
  // The part of ExpectedWalk(weight, levels_) in the significant cells: the
  // most that re-planning them can save.
  double SignificantWalk(const std::vector<double>& weight,
                         const std::vector<char>& significant) const;
  // The walk from a start of cell c at level r: sqrt(P / S) for a sub-grid
  // of the ideal shape, times how much more this shape's walks cross.
  double WalkTerm(size_t c, uint32_t r) const;
  // Makes `levels` the current table's levels (levels_, current_shapes_,
  // walk_terms_).
  void SetCurrentLevels(std::vector<uint32_t> levels);
  // The sub-grid that level r buys in coarse cell c: about r * r sub-cells
  // shaped by the cell's crossing ratio (1 x 1 for r = 1). A plan asks for
  // every cell's several times, mostly at its current level: those come
  // from current_shapes_.
  SubGrid ShapeOf(size_t c, uint32_t r) const;
  // ShapeOf() computed.
  SubGrid NewShape(size_t c, uint32_t r) const;
  std::vector<SubGrid> Shapes(const std::vector<uint32_t>& levels) const;
  // Fills points_, cbrt_points_ and crossing_ratio_ from the
  // triangulation's vertices and edges, once (a scan of all of them, or with
  // options_.mesh_larger_than_memory of a bounded sample of a large mesh's
  // faces: deferred to the first plan or restore, so that a tuner is cheap
  // to make and a server mapping a mesh larger than RAM reads none of it to
  // start).
  void MeasureCells();
  // table as the snapshot `version`, with the current histogram.
  std::shared_ptr<const TuningSnapshot> SnapshotOf(
      std::shared_ptr<const StartTable> table, uint64_t version) const;

  const ServingMesh& mesh_;
  const GridGeometry grid_;
  const TuningOptions options_;
  size_t budget_;
  size_t leaf_budget_;  // starts the plan may place beyond the coarse cells
  bool seen_traffic_ = false;
  // Walks re-tunes may still spend (kWorkPerQuery per query counted, at
  // most kWorkBurst).
  double work_credit_ = kWorkBurst;
  std::vector<double> counts_;
  std::vector<double> points_;       // vertices per coarse cell
  std::vector<double> cbrt_points_;  // their cube roots (for PlanLevels)
  // Edges crossed per unit width / per unit height, times the cell's
  // width / height: a walk across the cell's width crosses this many times
  // as many edges as one across its height.
  std::vector<double> crossing_ratio_;
  bool cells_measured_ = false;
  std::shared_ptr<const StartTable> table_;  // the last one built
  std::vector<uint32_t> levels_;             // the levels table_ was built at
  std::vector<SubGrid> current_shapes_;      // NewShape(c, levels_[c])
  std::vector<double> walk_terms_;     // WalkTerm(c, levels_[c]) for every c
  std::vector<double> planned_share_;  // traffic shares table_ was planned for
  // The shares the last planning saw (it may have kept the table), and the
  // fewest walks a growth it deferred for want of credit needs (HUGE_VAL:
  // none): until the traffic departs from those shares or the credit
  // reaches that, planning again would decide the same.
  std::vector<double> considered_share_;
  double deferred_walks_ = HUGE_VAL;
  // The build in progress (null when none), and what it was planned at.
  std::unique_ptr<StartTable::Builder> builder_;
  std::vector<uint32_t> building_levels_;
  std::vector<double> building_share_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_HOT_REGION_TUNER_H_
