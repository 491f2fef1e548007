// PlanTiles and BuildTiled (grid_tiles.h): tiles refined on several
// threads, then stitched.

#include "server/core/terrain/grid/grid_tiles.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

#include "server/core/terrain/grid/grid_refiner.h"

namespace locator {

namespace {

// Tiles per thread: enough that a thread finishing early finds work left.
constexpr unsigned kTilesPerThread = 4;
// No tile is narrower than this many cells: a cut line costs vertices.
constexpr int64_t kMinTileCells = 128;

// `parts` cut positions spreading (0, last) evenly, at most one per
// kMinTileCells.
std::vector<int64_t> Cuts(int64_t last, unsigned parts) {
  const auto count = static_cast<int64_t>(
      std::min<int64_t>(parts, std::max<int64_t>(1, last / kMinTileCells)));
  std::vector<int64_t> cuts;
  for (int64_t i = 1; i < count; ++i) cuts.push_back(last * i / count);
  return cuts;
}

GridRegion TileRegion(const ElevationGrid& grid, const TilePlan& plan, size_t i,
                      size_t j) {
  const auto edge = [](const std::vector<int64_t>& cuts, size_t k,
                       int64_t last) {
    return k == 0 ? 0 : (k > cuts.size() ? last : cuts[k - 1]);
  };
  const int64_t last_col = grid.width - int64_t{1};
  const int64_t last_row = grid.height - int64_t{1};
  GridRegion region;
  region.rect = GridRect{edge(plan.cut_cols, i, last_col),
                         edge(plan.cut_rows, j, last_row),
                         edge(plan.cut_cols, i + 1, last_col),
                         edge(plan.cut_rows, j + 1, last_row)};
  region.cut_left = i > 0;
  region.cut_right = i < plan.cut_cols.size();
  region.cut_top = j > 0;
  region.cut_bottom = j < plan.cut_rows.size();
  return region;
}

// One tile's result.
struct Tile {
  GridRegion region;
  TinMesh mesh{TinMesh::Coordinates::kGridIntegers};
  double max_error = 0;
  Status status;
};

// Stitches tiles into one mesh: vertices on a tile's border are shared by
// sample, and a border half-edge without a twin meets the one of the
// neighbouring tile that runs the other way, if there is one.
class Stitcher {
 public:
  Stitcher(const ElevationGrid& grid, TinMesh* mesh)
      : width_(grid.width), mesh_(mesh) {}

  void Add(const Tile& tile) {
    const TinMesh& m = tile.mesh;
    std::vector<uint32_t> id(m.num_vertices());
    std::vector<bool> shared(m.num_vertices());
    for (uint32_t v = 0; v < m.num_vertices(); ++v) {
      const Point2& p = m.point(v);
      const GridPoint g{static_cast<int64_t>(p.x), static_cast<int64_t>(p.y)};
      shared[v] = tile.region.rect.OnBorder(g);
      if (!shared[v]) {
        id[v] = mesh_->AddVertex(p);
        continue;
      }
      const auto [it, fresh] = border_vertices_.try_emplace(
          static_cast<uint64_t>(g.y) * width_ + g.x, 0);
      if (fresh) it->second = mesh_->AddVertex(p);
      id[v] = it->second;
    }
    const auto base = static_cast<uint32_t>(3 * mesh_->num_triangles());
    for (uint32_t t = 0; t < m.num_triangles(); ++t) {
      mesh_->AddTriangle(id[m.Corner(t, 0)], id[m.Corner(t, 1)],
                         id[m.Corner(t, 2)]);
    }
    for (uint32_t h = 0; h < 3 * m.num_triangles(); ++h) {
      const uint32_t twin = m.Twin(h);
      if (twin != TinMesh::kNoTwin) {
        if (h < twin) mesh_->Link(base + h, base + twin);
        if (m.IsConstrained(h)) mesh_->Constrain(base + h);
        continue;
      }
      const uint32_t a = m.Origin(h), b = m.Origin(TinMesh::Next(h));
      if (!shared[a] || !shared[b]) continue;
      // Keyed by (from, to); the neighbour's half-edge runs (to, from).
      const uint64_t key = (uint64_t{id[a]} << 32) | id[b];
      const uint64_t opposite = (uint64_t{id[b]} << 32) | id[a];
      if (const auto it = open_edges_.find(opposite); it != open_edges_.end()) {
        mesh_->Link(base + h, it->second);
        open_edges_.erase(it);
      } else {
        open_edges_.emplace(key, base + h);
      }
    }
  }

 private:
  const uint64_t width_;
  TinMesh* const mesh_;
  std::unordered_map<uint64_t, uint32_t> border_vertices_;
  std::unordered_map<uint64_t, uint32_t> open_edges_;
};

}  // namespace

TilePlan PlanTiles(const ElevationGrid& grid, unsigned threads) {
  TilePlan plan;
  if (threads <= 1) return plan;
  // Split the longer side more: tiles as square as they can be.
  const unsigned tiles = threads * kTilesPerThread;
  unsigned across = 1;
  while (across * across < tiles) ++across;
  unsigned down = (tiles + across - 1) / across;
  if (grid.height > grid.width) std::swap(across, down);
  plan.cut_cols = Cuts(grid.width - int64_t{1}, across);
  plan.cut_rows = Cuts(grid.height - int64_t{1}, down);
  return plan;
}

Status BuildTiled(const ElevationGrid& grid, const CellMask& mask,
                  const TinOptions& options, const TilePlan& plan,
                  unsigned threads, TinProgressReporter* progress,
                  TinMesh* mesh) {
  const std::vector<GridPoint> fixed =
      SimplifyCutLines(grid, mask, plan, options.max_error);
  const size_t across = plan.cut_cols.size() + 1;
  std::vector<std::unique_ptr<Tile>> tiles(plan.tiles());
  for (size_t k = 0; k < tiles.size(); ++k) {
    tiles[k] = std::make_unique<Tile>();
    tiles[k]->region = TileRegion(grid, plan, k % across, k / across);
  }
  std::atomic<size_t> next{0};
  const auto work = [&] {
    for (size_t k = next++; k < tiles.size(); k = next++) {
      Tile& tile = *tiles[k];
      std::vector<GridPoint> border;
      for (const GridPoint& p : fixed) {
        if (tile.region.rect.OnBorder(p)) border.push_back(p);
      }
      BuildRegionMesh(mask, tile.region.rect, border, &tile.mesh);
      GridRefiner refiner(grid, &tile.mesh, GridMetric::kPlane, tile.region,
                          options.max_error);
      refiner.ScanAll(1);
      tile.status = refiner.Refine(0, progress, k);
      tile.max_error = refiner.MaxError();
    }
  };
  std::vector<std::thread> helpers;
  for (unsigned i = 1; i < std::min<size_t>(threads, tiles.size()); ++i) {
    helpers.emplace_back(work);
  }
  work();
  for (std::thread& helper : helpers) helper.join();

  Stitcher stitcher(grid, mesh);
  double max_error = 0;
  for (std::unique_ptr<Tile>& tile : tiles) {
    if (!tile->status.ok()) return tile->status;
    stitcher.Add(*tile);
    max_error = std::max(max_error, tile->max_error);
    tile.reset();
  }
  progress->Merged(mesh->num_vertices(), max_error);
  return Status::OK();
}

}  // namespace locator
