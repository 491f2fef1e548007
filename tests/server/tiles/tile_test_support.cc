#include "tests/server/tiles/tile_test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>

#include "locator/dataset_sources.h"

namespace locator::test {

double Height(const Point2& p) {
  return 400 +
         120 * std::sin((p.x - kWest) / 700) * std::cos((p.y - kSouth) / 500) +
         0.01 * (p.y - kSouth);
}

std::unique_ptr<Engine> UtmTerrain(size_t n, const std::string& crs) {
  Dataset d = GenerateUniform(n, 17);
  for (Point2& p : d.points) {
    p = Point2{kWest + p.x * kSide, kSouth + p.y * kSide};
    d.values.push_back(Height(p));
  }
  d.crs = crs;
  StatusOr<std::unique_ptr<Engine>> built =
      Engine::Create(std::move(d), EngineOptions());
  EXPECT_TRUE(built.ok()) << built.status().ToString();
  return built.ok() ? *std::move(built) : nullptr;
}

// Cramer's rule on the two edges from corner 0.
FacetGradient PlaneGradient(const std::array<Point2, 3>& v,
                            const std::array<double, 3>& h) {
  const double h0 = h[0], h1 = h[1], h2 = h[2];
  const double ax = v[1].x - v[0].x, ay = v[1].y - v[0].y;
  const double bx = v[2].x - v[0].x, by = v[2].y - v[0].y;
  const double det = ax * by - ay * bx;
  return FacetGradient{((h1 - h0) * by - (h2 - h0) * ay) / det,
                       ((h2 - h0) * ax - (h1 - h0) * bx) / det};
}

FacetGradient Gradient(const LocateResult& r) {
  const std::array<Point2, 3>& v = r.vertices;
  return PlaneGradient(v, {Height(v[0]), Height(v[1]), Height(v[2])});
}

double Slope(const LocateResult& r) {
  const FacetGradient g = Gradient(r);
  return std::hypot(g.dz_dx, g.dz_dy);
}

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

TileAddress TileContaining(uint32_t z, const Point2& utm) {
  const std::unique_ptr<gis::CrsTransformer> to_mercator =
      MercatorUtmTransformer();
  std::vector<Point2> at = {utm};
  EXPECT_TRUE(to_mercator->ToRequest(at).ok());
  const double side = 2 * TileAddress::kHalfWorld / std::ldexp(1.0, z);
  return TileAddress{
      z, static_cast<uint32_t>((at[0].x + TileAddress::kHalfWorld) / side),
      static_cast<uint32_t>((TileAddress::kHalfWorld - at[0].y) / side)};
}

TileAddress TileAtSouthWestCorner(uint32_t z) {
  return TileContaining(z, Point2{kWest + 10, kSouth + 10});
}

}  // namespace locator::test
