#include "tests/server/tiles/tile_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace locator::test {

std::unique_ptr<gis::CrsTransformer> MercatorUtmTransformer() {
  StatusOr<std::unique_ptr<gis::CrsTransformer>> created =
      gis::CrsTransformer::Create("EPSG:3857", kUtm33);
  EXPECT_TRUE(created.ok()) << created.status().ToString();
  return created.ok() ? *std::move(created) : nullptr;
}

std::vector<Point2> PixelCentresInUtm33(const TileAddress& tile) {
  const double side = 2 * TileAddress::kHalfWorld / std::ldexp(1.0, tile.z);
  std::vector<Point2> centres;
  for (int row = 0; row < 256; ++row) {
    for (int col = 0; col < 256; ++col) {
      centres.push_back(
          {-TileAddress::kHalfWorld + (tile.x + (col + 0.5) / 256) * side,
           TileAddress::kHalfWorld - (tile.y + (row + 0.5) / 256) * side});
    }
  }
  const std::unique_ptr<gis::CrsTransformer> to_utm = MercatorUtmTransformer();
  if (to_utm == nullptr) return {};
  const Status moved = to_utm->ToDataset(centres);
  EXPECT_TRUE(moved.ok()) << moved.ToString();
  return centres;
}

}  // namespace locator::test
