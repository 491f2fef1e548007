#include "server/core/tiling/tiled_build.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tiling/build_checks.h"
#include "server/core/tiling/cells/halo_cells.h"
#include "server/core/tiling/cells/parallel.h"
#include "server/core/tiling/cells/sorted_points.h"
#include "server/core/tiling/hull_edges.h"
#include "server/core/tiling/mesh_assembly.h"
#include "server/core/tiling/tile_triangulation.h"

namespace locator {

namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// Triangulates every tile on `threads` threads, each with its own halo
// state; the first failure by tile order.
Status TriangulateTiles(const TileContext& context,
                        const std::vector<Tile>& tiles, unsigned threads,
                        std::vector<TileTriangles>* results) {
  results->resize(tiles.size());
  std::vector<Status> status(tiles.size());
  std::vector<std::unique_ptr<HaloCells>> halos(std::max(threads, 1u));
  ParallelTasks(tiles.size(), threads, [&](size_t t, size_t worker) {
    try {
      if (!halos[worker]) {
        halos[worker] =
            std::make_unique<HaloCells>(context.grid, context.source);
      }
      status[t] = TriangulateTile(context, tiles[t], halos[worker].get(),
                                  &(*results)[t]);
    } catch (const std::bad_alloc&) {
      status[t] = Status::ResourceExhausted(
          "out of memory triangulating tile " + std::to_string(t));
    } catch (const std::exception& e) {
      status[t] =
          Status::Internal("tile " + std::to_string(t) + ": " + e.what());
    }
  });
  for (Status& s : status) {
    if (!s.ok()) return s;
  }
  return Status::OK();
}

}  // namespace

size_t TileVerticesFor(size_t vertices, unsigned threads) {
  constexpr size_t kMinTile = size_t{1} << 15;
  const size_t tiles = 4 * size_t{std::max(threads, 1u)};
  return std::max(kMinTile, (vertices + tiles - 1) / tiles);
}

Status BuildTiledMesh(std::span<const Point2> points,
                      std::span<const double> values,
                      const TiledBuildOptions& options, BuiltMesh* out,
                      TiledBuildStats* stats) {
  TiledBuildStats local;
  if (stats == nullptr) stats = &local;
  const unsigned threads = std::max(options.threads, 1u);
  auto start = std::chrono::steady_clock::now();
  RETURN_IF_ERROR(CheckPointCoordinates(points, values.size()));
  if (points.size() > ServingMesh::kMaxElements) {
    return Status::InvalidArgument("dataset has " +
                                   std::to_string(points.size()) +
                                   " points; a serving mesh holds at most " +
                                   std::to_string(ServingMesh::kMaxElements));
  }
  SortedPoints sorted;
  SortPoints(points, std::max<size_t>(options.cell_points, 1), threads,
             &sorted);
  RETURN_IF_ERROR(
      CheckTriangulable(sorted.size(), AllCollinear(sorted.points)));
  const HullEdges hull = HullEdges::Compute(sorted.points, threads);
  stats->sort_seconds = SecondsSince(start);

  start = std::chrono::steady_clock::now();
  // The digest reads the input in id order; it runs beside the tiles.
  uint64_t digest = 0;
  std::thread digest_thread(
      [&] { digest = VertexDigestOf(points, sorted.ids); });
  const SortedPointsSource source(sorted);
  const TileContext context{sorted.grid, source, hull, sorted.size()};
  const std::vector<Tile> tiles = CutTiles(
      sorted.grid, source,
      options.tile_vertices > 0 ? options.tile_vertices
                                : TileVerticesFor(sorted.size(), threads));
  std::vector<TileTriangles> results;
  const Status tiled = TriangulateTiles(context, tiles, threads, &results);
  digest_thread.join();
  if (!tiled.ok()) return tiled;
  stats->tiles = tiles.size();
  stats->grid_level = sorted.grid.level();
  stats->halo_points = 0;
  stats->max_rounds = 0;
  for (const TileTriangles& r : results) {
    stats->halo_points += r.halo_points;
    stats->max_rounds = std::max(stats->max_rounds, r.rounds);
  }
  stats->tiles_seconds = SecondsSince(start);

  start = std::chrono::steady_clock::now();
  BuiltMesh built;
  built.facts.duplicates_merged = sorted.duplicates();
  RETURN_IF_ERROR(AssembleServingMesh(&sorted, &results, values, digest,
                                      threads, &built.mesh));
  built.facts.edge_sample = built.mesh->SampleEdges(kEdgeSampleSize);
  *out = std::move(built);
  stats->assembly_seconds = SecondsSince(start);
  return Status::OK();
}

}  // namespace locator
