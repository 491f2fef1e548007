// The tile set the tile-set and router tests serve: locator-build's tiles
// of a uniform CSV of 20,000 points, cut small (1,500 points a tile), and
// the shards and router over them; and the queries where tiles meet.
//
// Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_MAIN_TILE_SET_FIXTURE_H_
#define LOCATOR_TESTS_SERVER_MAIN_TILE_SET_FIXTURE_H_

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/channel_security.h"
#include "locator/geometry.h"
#include "locator/v1/locator.pb.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {

// The names of the files in `dir`, sorted.
std::vector<std::string> FilesIn(const std::string& dir);

// Tile corners and border midpoints, and the midpoints of edges whose ends
// are in different tiles, read from the tile files in `dir`.
std::vector<Point2> TileSeamQueries(const std::string& dir);

// A grid of `width` x `height` cells over the tile set (dataset "tiles")
// and beyond it (nodata -1 there).
v1::GridRequest GridAcrossTheTiles(uint32_t width, uint32_t height);

// Grids over the tile set (the default dataset) with a hostile value
// (HostileCoordinates(), hostile_values.h) in one field each, sizes past
// every limit (of 5000 cells), an unknown interpolation and a huge dataset
// name.
std::vector<v1::GridRequest> HostileGrids();

// Profiles across the tile set with a hostile value in one coordinate
// each, sample counts past the limit (of 300) and no vertices at all.
std::vector<v1::ProfileRequest> HostileProfiles();

class LocatordTileSetTest : public ::testing::Test {
 protected:
  // Builds the tile set (a failure is a test failure).
  void SetUp() override;

  // Two shards (--tiles 0/2 and 1/2) of the tile set, with `shard_flags`
  // added (and probed with `shard_security`), and a router over them with
  // `router_flags` added.
  void StartShardsAndRouter(const std::vector<std::string>& router_flags,
                            const std::vector<std::string>& shard_flags = {},
                            const ChannelSecurity& shard_security = {});

  ScratchDir dir_;
  std::string csv_;
  std::string tiles_;
  std::unique_ptr<ServerProcess> shard0_, shard1_, router_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_MAIN_TILE_SET_FIXTURE_H_
