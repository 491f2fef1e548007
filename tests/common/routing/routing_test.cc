// Routing by topology: a point's tile is the cell the tiled build cut it
// into (CellGrid), a shard map refuses topologies that do not add up, and a
// batch split by shard merges back into the input order with every column.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "common/routing/batch_split.h"
#include "common/routing/shard_map.h"
#include "common/routing/tile_router.h"
#include "server/core/tiling/cells/cell_grid.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

const BoundingBox kBox{-2, 10, 3, 12.5};

TEST(TileRouterTest, APointsCellIsTheCellTheTiledBuildCutItInto) {
  for (const int level : {0, 3, 7, 12}) {
    const CellGrid grid(kBox, level);
    StatusOr<TileRouter> router = TileRouter::Create(kBox, level, {0});
    ASSERT_TRUE(router.ok());
    std::mt19937_64 random(level);
    std::uniform_real_distribution<double> x(-3, 4), y(9, 13);
    for (int i = 0; i < 20000; ++i) {
      const Point2 p{x(random), y(random)};
      ASSERT_EQ(router->CellOf(p), grid.CellOfKey(grid.FineKey(p))) << level;
    }
  }
}

TEST(TileRouterTest, EveryPointHasATileEvenFarOutsideAndNaN) {
  StatusOr<TileRouter> router = TileRouter::Create(kBox, 2, {0, 5, 9, 15});
  ASSERT_TRUE(router.ok());
  const double kNaN = std::numeric_limits<double>::quiet_NaN();
  const double kInf = std::numeric_limits<double>::infinity();
  for (const Point2 p : {Point2{1e300, -1e300}, Point2{kNaN, 11},
                         Point2{kInf, -kInf}, Point2{4.9e-324, 11}}) {
    EXPECT_LT(router->TileOf(p), 4u);
  }
  EXPECT_EQ(router->TileOf({kNaN, kNaN}), 0u);  // cell 0
  EXPECT_EQ(router->end_cell(3), 16u);
  // Tile t holds exactly the cells [first_cell, end_cell).
  const CellGrid grid(kBox, 2);
  for (uint32_t cell = 0; cell < 16; ++cell) {
    uint32_t column = 0, row = 0;
    grid.CellPosition(cell, &column, &row);
    const Point2 centre{kBox.min_x + (column + 0.5) * kBox.width() / 4,
                        kBox.min_y + (row + 0.5) * kBox.height() / 4};
    const size_t tile = router->TileOf(centre);
    EXPECT_LE(router->first_cell(tile), cell);
    EXPECT_LT(cell, router->end_cell(tile));
  }
}

TEST(TileRouterTest, RefusesGridsThatAreNotTiles) {
  EXPECT_FALSE(TileRouter::Create(kBox, 2, {}).ok());
  EXPECT_FALSE(TileRouter::Create(kBox, 2, {1, 5}).ok());
  EXPECT_FALSE(TileRouter::Create(kBox, 2, {0, 5, 5}).ok());
  EXPECT_FALSE(TileRouter::Create(kBox, 2, {0, 16}).ok());
  EXPECT_FALSE(TileRouter::Create(kBox, 16, {0}).ok());
  EXPECT_FALSE(TileRouter::Create(kBox, -1, {0}).ok());
  EXPECT_FALSE(TileRouter::Create(
                   {0, 0, std::numeric_limits<double>::infinity(), 1}, 2, {0})
                   .ok());
  EXPECT_FALSE(TileRouter::Create({1, 0, 0, 1}, 2, {0}).ok());
}

// Four tiles on a level-2 grid, served by shards listing `shard_tiles`.
v1::GetTopologyResponse Topology(
    const std::vector<std::vector<uint32_t>>& shard_tiles) {
  v1::GetTopologyResponse topology;
  topology.set_dataset("big");
  topology.set_crs("EPSG:32633");
  topology.set_tiled(true);
  topology.mutable_bounds()->set_min_x(kBox.min_x);
  topology.mutable_bounds()->set_min_y(kBox.min_y);
  topology.mutable_bounds()->set_max_x(kBox.max_x);
  topology.mutable_bounds()->set_max_y(kBox.max_y);
  topology.set_grid_level(2);
  const uint32_t cuts[] = {0, 5, 9, 15, 16};
  for (int t = 0; t < 4; ++t) {
    v1::TopologyTile* tile = topology.add_tiles();
    tile->set_first_cell(cuts[t]);
    tile->set_end_cell(cuts[t + 1]);
  }
  for (size_t s = 0; s < shard_tiles.size(); ++s) {
    v1::TopologyShard* shard = topology.add_shards();
    shard->set_target("shard" + std::to_string(s) + ":50051");
    for (const uint32_t t : shard_tiles[s]) shard->add_tiles(t);
  }
  return topology;
}

TEST(ShardMapTest, RoutesEachTileToTheShardListingIt) {
  StatusOr<ShardMap> map = ShardMap::FromTopology(Topology({{0, 3}, {1, 2}}));
  ASSERT_TRUE(map.ok()) << map.status().ToString();
  EXPECT_TRUE(map->complete());
  EXPECT_TRUE(map->sharded());
  EXPECT_EQ(map->target(1), "shard1:50051");
  EXPECT_EQ(map->crs(), "EPSG:32633");
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> x(-3, 4), y(9, 13);
  for (int i = 0; i < 1000; ++i) {
    const Point2 p{x(random), y(random)};
    const size_t tile = map->TileOf(p);
    EXPECT_EQ(map->ShardOf(p), tile == 0 || tile == 3 ? 0u : 1u);
  }
}

TEST(ShardMapTest, RefusesTopologiesThatDoNotAddUp) {
  const auto refused = [](const v1::GetTopologyResponse& topology) {
    StatusOr<ShardMap> map = ShardMap::FromTopology(topology);
    return map.ok() ? std::string() : map.status().message();
  };
  EXPECT_THAT(refused(Topology({{0, 1}, {1, 2, 3}})),
              HasSubstr("lists tile 1, which another lists"));
  EXPECT_THAT(refused(Topology({{0, 1, 2, 3, 4}})),
              HasSubstr("tile 4, which does not exist"));
  EXPECT_THAT(refused(Topology({})), HasSubstr("lists no shard"));
  v1::GetTopologyResponse gap = Topology({{0, 1, 2, 3}});
  gap.mutable_tiles(1)->set_end_cell(8);
  EXPECT_THAT(refused(gap), HasSubstr("tile 1 does not end where"));
  v1::GetTopologyResponse deep = Topology({{0, 1, 2, 3}});
  deep.set_grid_level(4000000000u);
  EXPECT_THAT(refused(deep), HasSubstr("grid level"));

  // A tile without a shard is allowed, but its points have none.
  StatusOr<ShardMap> partial = ShardMap::FromTopology(Topology({{0, 1}}));
  ASSERT_TRUE(partial.ok());
  EXPECT_FALSE(partial->complete());
  const Point2 corner{kBox.max_x, kBox.min_y};  // the curve's last cell
  EXPECT_EQ(partial->TileOf(corner), 3u);
  EXPECT_EQ(partial->ShardOf(corner), ShardMap::kNoShard);
}

TEST(BatchSplitTest, MergesTheShardsAnswersBackInInputOrder) {
  StatusOr<ShardMap> map = ShardMap::FromTopology(Topology({{2}, {0, 3}, {1}}));
  ASSERT_TRUE(map.ok());
  v1::LocateBatchRequest request;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> x(-3, 4), y(9, 13);
  for (int i = 0; i < 500; ++i) {
    request.add_xs(x(random));
    request.add_ys(y(random));
  }
  request.set_include_vertex_ids(true);
  request.set_include_values(true);
  request.set_dataset("big");
  BatchSplit split;
  ASSERT_TRUE(SplitBatch(request, *map, &split).ok());
  ASSERT_EQ(split.parts.size(), 3u);
  // Each shard "answers" from the point alone, as the whole mesh would.
  std::vector<v1::LocateBatchResponse> answers(3);
  for (size_t s = 0; s < 3; ++s) {
    EXPECT_EQ(split.parts[s].dataset(), "big");
    EXPECT_TRUE(split.parts[s].include_values());
    for (int j = 0; j < split.parts[s].xs_size(); ++j) {
      const double px = split.parts[s].xs(j);
      EXPECT_EQ(map->ShardOf({px, split.parts[s].ys(j)}), s);
      answers[s].add_types(v1::LOCATION_TYPE_FACE);
      answers[s].add_triangle_ids(static_cast<int64_t>(px * 1000));
      answers[s].add_costs(j);
      for (int k = 0; k < 3; ++k) answers[s].add_vertex_ids(k);
      answers[s].add_values(px * 2);
    }
    answers[s].set_total_cost(10);
  }
  v1::LocateBatchResponse merged;
  ASSERT_TRUE(MergeBatch(request, split, answers, &merged).ok());
  ASSERT_EQ(merged.triangle_ids_size(), 500);
  ASSERT_EQ(merged.vertex_ids_size(), 1500);
  EXPECT_EQ(merged.barycentric_size(), 0);
  for (int i = 0; i < 500; ++i) {
    EXPECT_EQ(merged.triangle_ids(i),
              static_cast<int64_t>(request.xs(i) * 1000));
    EXPECT_EQ(merged.values(i), request.xs(i) * 2);
  }
  EXPECT_EQ(merged.total_cost(), 30u);

  // A shard answering for other points is caught, naming it.
  answers[1].add_types(v1::LOCATION_TYPE_FACE);
  const Status wrong = MergeBatch(request, split, answers, &merged);
  EXPECT_EQ(wrong.code(), Status::Code::kUnavailable);
  EXPECT_THAT(wrong.message(), HasSubstr("shard 1"));
}

TEST(BatchSplitTest, RefusesWhatCannotBeRouted) {
  StatusOr<ShardMap> map = ShardMap::FromTopology(Topology({{0, 1, 2}}));
  ASSERT_TRUE(map.ok());
  v1::LocateBatchRequest request;
  request.add_xs(kBox.min_x);
  request.add_ys(kBox.min_y);  // cell 0: tile 0
  BatchSplit split;
  EXPECT_TRUE(SplitBatch(request, *map, &split).ok());
  request.add_xs(kBox.max_x);
  request.add_ys(kBox.min_y);  // the last cell: tile 3, no shard
  const Status none = SplitBatch(request, *map, &split);
  EXPECT_EQ(none.code(), Status::Code::kFailedPrecondition);
  EXPECT_THAT(none.message(), HasSubstr("point 1 (3, 10) lies in tile 3"));
  request.add_xs(0);
  EXPECT_EQ(SplitBatch(request, *map, &split).code(),
            Status::Code::kInvalidArgument);
  // A batch with a crs is routed by its points in the dataset's CRS, and
  // sent with its own.
  v1::LocateBatchRequest with_crs;
  with_crs.set_crs("EPSG:4326");
  with_crs.add_xs(15);
  with_crs.add_ys(49.6);
  EXPECT_THAT(SplitBatch(with_crs, *map, &split).message(),
              HasSubstr("routed by its points in the dataset's CRS"));
  const Point2 where[] = {{kBox.min_x, kBox.min_y}};  // tile 0
  ASSERT_TRUE(SplitBatch(with_crs, *map, &split, where).ok());
  ASSERT_EQ(split.parts[0].xs_size(), 1);
  EXPECT_EQ(split.parts[0].xs(0), 15);
  EXPECT_EQ(split.parts[0].crs(), "EPSG:4326");
  EXPECT_EQ(split.positions[0], std::vector<uint32_t>{0});
}

}  // namespace
}  // namespace locator
