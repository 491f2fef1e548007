// HotRegionTuner's re-tunes: a hot spot appearing on a table planned for
// uniform traffic rebuilds the hot spot's cells and keeps every other one,
// within the memory budget, even when keeping them leaves the hot cells less
// than the fresh plan would give them.

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
  // The traffic of the hot spot: 1000 queries in each hot cell.
  std::vector<double> HotCounts() const {
    std::vector<double> counts(grid().cells(), 0.0);
    for (size_t c = 0; c < counts.size(); ++c) {
      counts[c] = IsHotCell(c) ? 1000 : 0;
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

}  // namespace
}  // namespace locator
