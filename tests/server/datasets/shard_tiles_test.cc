// ShardTiles: which tiles `locatord --tiles SELECTOR` serves, the
// selector's errors, and a shard's refusal of points of other tiles.

#include "server/datasets/shard_tiles.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace locator {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Ten tiles on a level-2 grid over the unit square.
TileRouter TenTiles() {
  return *TileRouter::Create({0, 0, 1, 1}, 2,
                             {0, 1, 2, 3, 5, 7, 9, 11, 13, 15});
}

std::vector<uint32_t> Served(std::string_view selector) {
  StatusOr<std::shared_ptr<const ShardTiles>> tiles =
      ShardTiles::Select(TenTiles(), selector, 7);
  EXPECT_TRUE(tiles.ok()) << tiles.status().ToString();
  return tiles.ok() ? (*tiles)->served() : std::vector<uint32_t>();
}

std::string Refusal(std::string_view selector) {
  StatusOr<std::shared_ptr<const ShardTiles>> tiles =
      ShardTiles::Select(TenTiles(), selector, 7);
  return tiles.ok() ? "" : tiles.status().message();
}

TEST(ShardTilesTest, SelectsPartsListsAndRanges) {
  EXPECT_EQ(Served("").size(), 10u);
  EXPECT_THAT(Served("0/3"), ElementsAre(0, 1, 2));
  EXPECT_THAT(Served("1/3"), ElementsAre(3, 4, 5));
  EXPECT_THAT(Served("2/3"), ElementsAre(6, 7, 8, 9));
  EXPECT_THAT(Served("5,0-2,2-3"), ElementsAre(0, 1, 2, 3, 5));
  EXPECT_THAT(Served("9"), ElementsAre(9));
  StatusOr<std::shared_ptr<const ShardTiles>> all =
      ShardTiles::Select(TenTiles(), "", 7);
  ASSERT_TRUE(all.ok());
  EXPECT_TRUE((*all)->serves_all());
  EXPECT_EQ((*all)->fingerprint(), 7u);
}

TEST(ShardTilesTest, RefusesSelectorsNamingWhatIsWrong) {
  EXPECT_THAT(Refusal("3/3"), HasSubstr("expected K/N with 0 <= K < N"));
  EXPECT_THAT(Refusal("1/0"), HasSubstr("expected K/N"));
  EXPECT_THAT(Refusal("0/12"), HasSubstr("gets no tile"));
  EXPECT_THAT(Refusal("0-10"), HasSubstr("tile 10 does not exist"));
  EXPECT_THAT(Refusal("5-2"), HasSubstr("ranges like 0-9,12"));
  EXPECT_THAT(Refusal("1,,2"), HasSubstr("ranges like 0-9,12"));
  EXPECT_THAT(Refusal("-1"), HasSubstr("ranges like 0-9,12"));
  EXPECT_THAT(Refusal("0x3"), HasSubstr("ranges like 0-9,12"));
  EXPECT_THAT(Refusal(std::string(5000, '1')), HasSubstr("longer than 4096"));
  // The syntax check at startup never expands ranges, however wide.
  EXPECT_TRUE(ShardTiles::CheckSelector("0-4000000000").ok());
  EXPECT_TRUE(ShardTiles::CheckSelector("3/4").ok());
  EXPECT_FALSE(ShardTiles::CheckSelector("3/").ok());
}

TEST(ShardTilesTest, ServesItsTilesAndRefusesOthersNamingThePoint) {
  StatusOr<std::shared_ptr<const ShardTiles>> tiles =
      ShardTiles::Select(TenTiles(), "0/2", 7);
  ASSERT_TRUE(tiles.ok());
  const ShardTiles& shard = **tiles;
  // Cell 0 is the lower left, cell 15 the lower right (Hilbert order).
  const std::vector<Point2> own = {{0.1, 0.1}, {-5, -5}};
  EXPECT_TRUE(shard.CheckServed(own, 0).ok());
  const std::vector<Point2> mixed = {{0.1, 0.1}, {0.9, 0.1}};
  const Status refused = shard.CheckServed(mixed, 40);
  EXPECT_EQ(refused.code(), Status::Code::kFailedPrecondition);
  EXPECT_THAT(refused.message(),
              HasSubstr("point 41 (0.9, 0.1) lies in tile 9, which this "
                        "server does not serve (--tiles '0/2')"));
}

}  // namespace
}  // namespace locator
