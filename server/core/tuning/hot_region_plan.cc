// HotRegionTuner's planning (hot_region_tuner.h): from the histogram to the
// levels of the next table, under the memory budget and the work credit.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "server/core/tuning/hot_region_tuner.h"

namespace locator {

namespace {

// Starts per vertex a cell may have: about 2 per triangle, so that a
// query's sub-cell is mostly smaller than its triangle and the walk often
// starts in it (1.42 faces per query on a hot spot at n = 10^6, against
// 1.70 at 1.5 per vertex). Deeper cells buy little more and make the
// re-tunes that follow a moving hot spot build more (at 6 per vertex, 1.34
// faces, but drift's tuner share rose from 0.54 to 0.67).
constexpr double kStartsPerPointCap = 4;

}  // namespace

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

}  // namespace locator
