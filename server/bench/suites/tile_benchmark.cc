#include "server/bench/suites/tile_benchmark.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <string>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/status_macros.h"
#include "locator/engine.h"
#include "server/bench/datasets/surface_terrain.h"
#include "server/bench/stopwatch.h"
#include "server/tiles/hillshade.h"
#include "server/tiles/terrain_tile.h"

namespace locator::bench {
namespace {

// Where the terrain's 10 km square goes in UTM zone 33N (near 15°E 49.6°N).
constexpr double kEasting = 500000, kNorthing = 5500000;
constexpr char kCrs[] = "EPSG:32633";

// The terrain's centre in EPSG:3857.
StatusOr<Point2> MercatorCentre() {
  ASSIGN_OR_RETURN(std::unique_ptr<gis::CrsTransformer> transformer,
                   gis::CrsTransformer::Create("EPSG:3857", kCrs));
  const BoundingBox box = TerrainBox();
  std::vector<Point2> centre = {{kEasting + (box.min_x + box.max_x) / 2,
                                 kNorthing + (box.min_y + box.max_y) / 2}};
  RETURN_IF_ERROR(transformer->ToRequest(centre));
  return centre[0];
}

// Up to `count` tiles of zoom `z` nearest `centre`, in rings around it.
std::vector<TileAddress> TilesAround(const Point2& centre, uint32_t z,
                                     int count) {
  const double side = 2 * TileAddress::kHalfWorld / std::ldexp(1.0, z);
  const int64_t cx =
      static_cast<int64_t>((centre.x + TileAddress::kHalfWorld) / side);
  const int64_t cy =
      static_cast<int64_t>((TileAddress::kHalfWorld - centre.y) / side);
  const int64_t last = (int64_t{1} << z) - 1;
  std::vector<TileAddress> tiles;
  for (int64_t ring = 0; static_cast<int>(tiles.size()) < count && ring <= last;
       ++ring) {
    for (int64_t dy = -ring; dy <= ring; ++dy) {
      for (int64_t dx = -ring; dx <= ring; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != ring) continue;
        const int64_t x = cx + dx, y = cy + dy;
        if (x < 0 || y < 0 || x > last || y > last) continue;
        if (static_cast<int>(tiles.size()) == count) continue;
        tiles.push_back(
            TileAddress{z, static_cast<uint32_t>(x), static_cast<uint32_t>(y)});
      }
    }
  }
  return tiles;
}

}  // namespace

Status RunTileBenchmark(const TileBenchOptions& options, std::ostream& out) {
  Dataset terrain = TerrainDataset(options.points, 42);
  for (Point2& p : terrain.points) p = Point2{p.x + kEasting, p.y + kNorthing};
  terrain.crs = kCrs;
  // The default strategy, self-tuning, as locatord serves.
  ASSIGN_OR_RETURN(std::unique_ptr<Engine> engine,
                   Engine::Create(std::move(terrain), EngineOptions()));
  StatusOr<Point2> centre = MercatorCentre();
  if (!centre.ok()) return centre.status();
  // The first tile made on a thread also makes its PROJ transformer.
  RETURN_IF_ERROR(RenderTerrainTile(*engine, "terrain", TileAddress{0, 0, 0},
                                    TerrainEncoding::kTerrarium)
                      .status());

  out << "tile benchmark: " << options.points << " points in " << kCrs
      << ", 256x256 terrarium tiles, single thread\n"
      << "zoom | tiles | ms per tile (mean) | max ms | of which: PROJ ms | "
         "walk ms | encode+PNG ms | PNG bytes | hillshade ms (mean)\n";
  std::vector<Point2> pixels;
  std::vector<double> heights(TileAddress::kPixels * TileAddress::kPixels);
  for (uint32_t z = 11; z <= 17; ++z) {
    const std::vector<TileAddress> tiles =
        TilesAround(*centre, z, options.tiles);
    double total = 0, worst = 0, proj = 0, walk = 0, shade = 0;
    size_t bytes = 0;
    for (const TileAddress& tile : tiles) {
      Stopwatch watch;
      StatusOr<std::string> png = RenderTerrainTile(
          *engine, "terrain", tile, TerrainEncoding::kTerrarium);
      if (!png.ok()) return png.status();
      const double seconds = watch.Seconds();
      total += seconds;
      worst = std::max(worst, seconds);
      bytes += png->size();
      // The parts, timed again on their own.
      watch.Restart();
      RETURN_IF_ERROR(TilePixelsInDatasetCrs(*engine, tile, &pixels));
      proj += watch.Seconds();
      watch.Restart();
      RETURN_IF_ERROR(engine->RenderPoints(pixels, TileAddress::kPixels,
                                           Interpolation::kLinear, 0,
                                           heights.data()));
      walk += watch.Seconds();
      watch.Restart();
      RETURN_IF_ERROR(
          RenderHillshadeTile(*engine, "terrain", tile, HillshadeOptions())
              .status());
      shade += watch.Seconds();
    }
    const double n = static_cast<double>(tiles.size());
    out << std::fixed << std::setprecision(2) << std::setw(4) << z << " | "
        << std::setw(5) << tiles.size() << " | " << std::setw(18)
        << total / n * 1e3 << " | " << std::setw(6) << worst * 1e3 << " | "
        << std::setw(17) << proj / n * 1e3 << " | " << std::setw(7)
        << walk / n * 1e3 << " | " << std::setw(13)
        << (total - proj - walk) / n * 1e3 << " | " << std::setw(9)
        << static_cast<size_t>(bytes / n) << " | " << std::setw(19)
        << shade / n * 1e3 << "\n";
  }
  return Status::OK();
}

}  // namespace locator::bench
