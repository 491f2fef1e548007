// HotRegionTuner's re-tunes: a hot spot appearing on a table planned for
// uniform traffic rebuilds the hot spot's cells and keeps every other one,
// within the memory budget, even when keeping them leaves the hot cells less
// than the fresh plan would give them; re-tunes walk no more than their
// queries pay for.

#include "server/core/tuning/hot_region_tuner.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"

namespace locator {
namespace {

constexpr int kTunerGrid = 16;
// 48 of the 256 cells, an 8 x 6 block, take all the traffic. The budget
// buys about 30,000 starts beyond the coarse cells (1.5 per point): planned
// for uniform traffic, about 100 per cell. The fresh plan caps the hot
// cells near 4 starts per point (about 310 each) and gives the others about
// 58, within hysteresis of their 100, so they are kept; but then the hot
// cells' fresh plans no longer fit.
constexpr int kTunerHotColumns = 8;
constexpr int kTunerHotRows = 6;
constexpr size_t kTunerBudgetBytes = 147'000;

bool IsHotCell(size_t cell) {
  return cell / kTunerGrid < kTunerHotRows &&
         cell % kTunerGrid < kTunerHotColumns;
}

// 20,000 uniform points and the tuners' grid over them.
class HotRegionTunerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    StatusOr<std::unique_ptr<Triangulation>> built =
        Triangulation::Build(GenerateUniform(20'000, 3));
    ASSERT_TRUE(built.ok()) << built.status().ToString();
    triangulation_ = *std::move(built);
  }
  const ServingMesh& mesh() const { return triangulation_->mesh(); }
  GridGeometry grid() const {
    return GridGeometry(triangulation_->bounding_box(), kTunerGrid);
  }
  // The traffic of the hot spot: `queries` in each hot cell, the block
  // shifted right by `shift` columns.
  std::vector<double> HotCounts(double queries = 1000, size_t shift = 0) const {
    std::vector<double> counts(grid().cells(), 0.0);
    for (size_t c = 0; c < counts.size(); ++c) {
      const size_t column = c % kTunerGrid;
      counts[c] = column >= shift && IsHotCell(c - shift) ? queries : 0;
    }
    return counts;
  }

  std::unique_ptr<Triangulation> triangulation_;
};

TEST_F(HotRegionTunerTest, AHotSpotRebuildsItsCellsAndKeepsTheOthers) {
  const ServingMesh& mesh = this->mesh();
  const GridGeometry grid = this->grid();
  TuningOptions options;
  options.budget_bytes = kTunerBudgetBytes;
  HotRegionTuner tuner(mesh, grid, options, 0);
  const std::shared_ptr<const TuningSnapshot> uniform = tuner.Build(1);

  tuner.AddCounts(HotCounts());
  const std::shared_ptr<const TuningSnapshot> hot = tuner.Build(2);

  ASSERT_NE(hot->table, uniform->table) << "the hot spot must re-tune";
  for (size_t c = 0; c < grid.cells(); ++c) {
    const SubGrid before = uniform->table->sub_grid(c);
    const SubGrid after = hot->table->sub_grid(c);
    if (IsHotCell(c)) {
      EXPECT_GT(after.cells(), before.cells()) << "hot cell " << c;
    } else {
      EXPECT_EQ(after, before) << "cold cell " << c << " was rebuilt";
    }
  }
  EXPECT_LE(hot->table->MemoryBytes(), tuner.budget_bytes());
  // Refined cells' starts are faces; an unrefined cell's may wait for its
  // first use.
  const std::vector<StartTable::Face> starts = hot->table->Starts();
  size_t start = 0;
  for (size_t c = 0; c < grid.cells(); ++c) {
    const size_t n = hot->table->sub_grid(c).cells();
    for (size_t k = 0; k < n; ++k, ++start) {
      if (n == 1 && starts[start] == StartTable::kUnresolved) continue;
      ASSERT_LT(starts[start], mesh.num_faces());
    }
  }
}

// A mesh larger than RAM is tuned only where traffic goes: no table before
// any, and then only the cells with traffic refined, the others left to find
// their start on first use.
TEST_F(HotRegionTunerTest, AMeshLargerThanMemoryIsTunedOnlyWhereTrafficIs) {
  const GridGeometry grid = this->grid();
  TuningOptions options;
  options.budget_bytes = kTunerBudgetBytes;
  options.mesh_larger_than_memory = true;
  HotRegionTuner tuner(mesh(), grid, options, 0);
  const std::shared_ptr<const TuningSnapshot> idle = tuner.Build(1);
  for (const StartTable::Face face : idle->table->Starts()) {
    EXPECT_EQ(face, StartTable::kUnresolved);
  }

  tuner.AddCounts(HotCounts());
  const std::shared_ptr<const TuningSnapshot> hot = tuner.Build(2);
  for (size_t c = 0; c < grid.cells(); ++c) {
    if (IsHotCell(c)) {
      EXPECT_GT(hot->table->sub_grid(c).cells(), 1u) << "hot cell " << c;
    } else {
      EXPECT_EQ(hot->table->sub_grid(c).cells(), 1u) << "cold cell " << c;
    }
  }
}

// Re-tunes pay for themselves: a hot spot that keeps moving is refined only
// as far as kWorkPerQuery walks per query (after the burst) pay for, and a
// hot spot that then stays is learned whole over the re-tunes that follow.
TEST_F(HotRegionTunerTest, ReTunesWalkNoMoreThanTheirQueriesPayFor) {
  const GridGeometry grid = this->grid();
  TuningOptions options;
  options.budget_bytes = kTunerBudgetBytes;
  HotRegionTuner tuner(mesh(), grid, options, 0);
  const std::shared_ptr<const TuningSnapshot> uniform = tuner.Build(1);
  std::shared_ptr<const TuningSnapshot> last = uniform;
  double queries = 0, grown = 0;
  // Walks for the cells whose sub-grid grew since the last snapshot.
  const auto grew = [&](const TuningSnapshot& next) {
    double walks = 0;
    for (size_t c = 0; c < grid.cells(); ++c) {
      const size_t before = last->table->sub_grid(c).cells();
      const size_t after = next.table->sub_grid(c).cells();
      if (after > before) walks += static_cast<double>(after);
    }
    return walks;
  };
  // 10 queries per hot cell per re-tune, 480 in all: 120 walks of credit.
  constexpr double kPerCell = 10;
  const double per_retune = kPerCell * kTunerHotColumns * kTunerHotRows;
  for (int retune = 0; retune < 40; ++retune) {
    tuner.AddCounts(HotCounts(kPerCell, retune % 2 == 0 ? 0 : 8));
    queries += per_retune;
    const std::shared_ptr<const TuningSnapshot> next = tuner.Build(2 + retune);
    grown += grew(*next);
    ASSERT_LE(grown, HotRegionTuner::kWorkBurst +
                         HotRegionTuner::kWorkPerQuery * queries)
        << "re-tune " << retune;
    EXPECT_LE(next->table->MemoryBytes(), tuner.budget_bytes());
    last = next;
  }
  // The spot stays on the left: re-tunes enough to pay for the cap (4
  // starts per point) in every hot cell refine all of them, to within the
  // hysteresis of their plans.
  const double cap = 48 * 4 * 20'000.0 / (kTunerGrid * kTunerGrid);
  const int stay =
      static_cast<int>(cap / (HotRegionTuner::kWorkPerQuery * per_retune) + 20);
  double hot = 0, before = 0;
  for (int retune = 0; retune < stay; ++retune) {
    tuner.AddCounts(HotCounts(kPerCell, 0));
    last = tuner.Build(100 + retune);
  }
  for (size_t c = 0; c < grid.cells(); ++c) {
    if (!IsHotCell(c)) continue;
    const size_t cells = last->table->sub_grid(c).cells();
    EXPECT_GT(cells, uniform->table->sub_grid(c).cells()) << "hot cell " << c;
    hot += static_cast<double>(cells);
    before += static_cast<double>(uniform->table->sub_grid(c).cells());
  }
  EXPECT_GT(hot, 1.5 * before);
}

}  // namespace
}  // namespace locator
