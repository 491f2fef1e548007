#include "server/bench/suites/quantized_mesh_benchmark.h"

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
#include "server/tiles/quantized_mesh/quantized_mesh_tile.h"

namespace locator::bench {
namespace {

// Where the terrain goes in UTM zone 33N (near 15°E 49.6°N), as in the
// PNG tiles' benchmark.
constexpr double kMeshEasting = 500000, kMeshNorthing = 5500000;
constexpr char kMeshCrs[] = "EPSG:32633";
constexpr uint32_t kDeepestLevel = 16;

}  // namespace

Status RunQuantizedMeshBenchmark(const QuantizedMeshBenchOptions& options,
                                 std::ostream& out) {
  Dataset terrain = TerrainDataset(options.points, 42);
  for (Point2& p : terrain.points)
    p = Point2{p.x + kMeshEasting, p.y + kMeshNorthing};
  terrain.crs = kMeshCrs;
  ASSIGN_OR_RETURN(std::unique_ptr<Engine> engine,
                   Engine::Create(std::move(terrain), EngineOptions()));
  ASSIGN_OR_RETURN(std::unique_ptr<gis::CrsTransformer> transformer,
                   gis::CrsTransformer::Create("EPSG:4326", kMeshCrs));
  const BoundingBox box = TerrainBox();
  std::vector<Point2> centre = {{kMeshEasting + (box.min_x + box.max_x) / 2,
                                 kMeshNorthing + (box.min_y + box.max_y) / 2}};
  RETURN_IF_ERROR(transformer->ToRequest(centre));
  // The first tile made on a thread also makes its PROJ transformer.
  RETURN_IF_ERROR(
      RenderQuantizedMesh(*engine, "terrain", GeographicTile{0, 0, 0})
          .status());

  out << "quantized-mesh benchmark: " << options.points << " points in "
      << kMeshCrs << ", the 2 x 2 tiles round the centre, single thread\n"
      << "level | geometric error m | ms per tile (mean) | max ms | bytes "
         "(mean)\n";
  for (uint32_t z = 0; z <= kDeepestLevel; ++z) {
    const double side = std::ldexp(180.0, -static_cast<int>(z));
    const uint32_t x = static_cast<uint32_t>((centre[0].x + 180) / side);
    const uint32_t y = static_cast<uint32_t>((centre[0].y + 90) / side);
    double total = 0, worst = 0;
    size_t bytes = 0, tiles = 0;
    for (uint32_t dx : {0u, 1u}) {
      for (uint32_t dy : {0u, 1u}) {
        if (y + dy >= (uint32_t{1} << z)) continue;
        Stopwatch watch;
        StatusOr<std::string> tile =
            RenderQuantizedMesh(*engine, "terrain", {z, x + dx, y + dy});
        if (!tile.ok()) return tile.status();
        const double seconds = watch.Seconds();
        total += seconds;
        worst = std::max(worst, seconds);
        bytes += tile->size();
        ++tiles;
      }
    }
    out << std::fixed << std::setprecision(2) << std::setw(5) << z << " | "
        << std::setw(17) << GeometricError(z) << " | " << std::setw(18)
        << total / tiles * 1e3 << " | " << std::setw(6) << worst * 1e3 << " | "
        << bytes / tiles << "\n";
  }
  return Status::OK();
}

}  // namespace locator::bench
