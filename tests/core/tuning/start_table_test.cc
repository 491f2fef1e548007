// StartTable's unrefined cells find their start on first use: building a
// table reads none of the mesh for them, the first Start() in a cell finds
// the face holding its centre (as a walk from anywhere does), stores it for
// every later query, and queries racing to resolve one cell agree.

#include "server/core/tuning/start_table.h"

#include <gtest/gtest.h>

#include <memory>
#include <thread>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/mesh_walk.h"

namespace locator {
namespace {

TEST(StartTableTest, AnUnrefinedCellFindsItsStartOnFirstUse) {
  StatusOr<std::unique_ptr<Triangulation>> built =
      Triangulation::Build(GenerateUniform(5'000, 4));
  ASSERT_TRUE(built.ok()) << built.status().ToString();
  const ServingMesh& mesh = (*built)->mesh();
  const GridGeometry grid((*built)->bounding_box(), 8);
  std::vector<SubGrid> shapes(grid.cells());
  shapes[9] = SubGrid{3, 2};  // one refined cell, built at once
  const StartTable table(mesh, grid, shapes);
  std::vector<StartTable::Face> starts = table.Starts();
  ASSERT_EQ(starts.size(), grid.cells() - 1 + 6);
  for (size_t i = 0; i < starts.size(); ++i) {
    const bool refined = i >= 9 && i < 15;
    EXPECT_EQ(starts[i] == StartTable::kUnresolved, !refined) << i;
  }

  // Every cell's centre, from several threads at once, twice.
  std::vector<Point2> centres;
  for (int row = 0; row < grid.size(); ++row) {
    for (int col = 0; col < grid.size(); ++col) {
      const BoundingBox box = grid.CellBox(col, row);
      centres.push_back(
          {(box.min_x + box.max_x) / 2, (box.min_y + box.max_y) / 2});
    }
  }
  std::vector<std::vector<StartTable::Face>> seen(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < seen.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int pass = 0; pass < 2; ++pass) {
        for (const Point2& c : centres) {
          uint32_t lookups = 0;
          seen[t].push_back(table.Start(c, &lookups));
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (size_t t = 1; t < seen.size(); ++t) EXPECT_EQ(seen[t], seen[0]);
  starts = table.Starts();
  for (size_t c = 0; c < centres.size(); ++c) {
    if (c == 9) continue;
    const size_t at = c < 9 ? c : c + 5;
    ASSERT_LT(starts[at], mesh.num_faces());
    EXPECT_EQ(starts[at], seen[0][c]);
    EXPECT_EQ(starts[at], FaceNear(mesh, mesh.DefaultStart(), centres[c]));
  }

  // A re-tune keeping the cells keeps what they found.
  const StartTable next(mesh, grid, shapes, &table);
  EXPECT_EQ(next.Starts(), starts);
}

}  // namespace
}  // namespace locator
