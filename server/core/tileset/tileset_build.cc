#include "server/core/tileset/tileset_build.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <span>
#include <vector>

#include "common/status_macros.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/core/tileset/binary_files.h"
#include "server/core/tileset/point_bins.h"
#include "server/core/tileset/tileset_mesh.h"
#include "server/core/tiling/build_checks.h"
#include "server/core/tiling/cells/halo_cells.h"
#include "server/core/tiling/cells/parallel.h"
#include "server/core/tiling/hull_edges.h"
#include "server/core/tiling/tile_triangulation.h"

namespace locator {
namespace {

// Bytes per point of a bin sorted in memory, and of a tile's triangulation
// (its halo, CGAL's faces and the owned triangles), with room to spare.
constexpr size_t kBinBytesPerPoint = 80;
constexpr size_t kTileBytesPerPoint = 800;
constexpr size_t kMinTilePoints = size_t{1} << 15;
// Bytes per triangle of the mesh assembly's bins sorted in memory.
constexpr size_t kMeshBytesPerTriangle = 100;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

Status MakeDirectory(const std::string& dir) {
  if (::mkdir(dir.c_str(), 0755) == 0 || errno == EEXIST) return Status::OK();
  return Status::IOError("cannot create directory '" + dir + "'");
}

uint64_t KeyOf(std::initializer_list<uint64_t> parts, std::string_view text) {
  Xxh3Digest digest;
  for (const uint64_t part : parts) digest.AddU64(part);
  digest.Add(text);
  return digest.digest();
}

// The sorted points of the source in `work`: an earlier run's, or binned
// now.
Status SortedPointsOf(PointStream* stream, const std::string& work,
                      const TileSetOptions& options, uint64_t key,
                      BinnedPoints* binned, TileSetStats* stats) {
  if (LoadBinnedPoints(work, key, binned).ok()) {
    RandomAccessFile points, input;
    if (points.Open(BinnedPointsPath(work)).ok() &&
        points.size() == binned->vertices * sizeof(Point2) &&
        input.Open(InputPointsPath(work)).ok() &&
        input.size() == binned->input_points * sizeof(Point2)) {
      stats->bins_reused = true;
      return Status::OK();
    }
  }
  BinningOptions binning;
  binning.cell_points = options.cell_points;
  binning.bin_points = std::max<size_t>(
      options.memory_bytes / kBinBytesPerPoint, kMinTilePoints);
  return BinPoints(stream, work, binning, key, binned);
}

// The hull of all vertices, from the bins' candidates.
Status HullOf(const BinnedPoints& binned, const RandomAccessFile& points,
              unsigned threads, HullEdges* hull) {
  std::vector<Point2> candidates(binned.hull_candidates.size());
  for (size_t k = 0; k < candidates.size(); ++k) {
    RETURN_IF_ERROR(points.ReadItems(binned.hull_candidates[k],
                                     std::span<Point2>(&candidates[k], 1)));
  }
  RETURN_IF_ERROR(CheckTriangulable(binned.vertices, AllCollinear(candidates)));
  *hull = HullEdges::Compute(candidates, threads)
              .Renumbered(binned.hull_candidates);
  return Status::OK();
}

// Reads a tile's own vertices from the work files and writes its file.
class TileWriter {
 public:
  TileWriter(const std::string& work, const std::string& dir,
             const BinnedPoints& binned)
      : dir_(dir), binned_(binned) {
    opened_ = points_.Open(BinnedPointsPath(work));
    if (opened_.ok()) opened_ = ids_.Open(BinnedIdsPath(work));
    if (opened_.ok() && binned.has_values) {
      opened_ = values_.Open(BinnedValuesPath(work));
    }
  }
  const Status& opened() const { return opened_; }
  const RandomAccessFile& points() const { return points_; }

  Status Write(const TileTriangles& triangles,
               TileSetManifest::TileEntry* entry) const {
    const Tile& tile = entry->info.tile;
    const size_t n = tile.end_vertex - tile.first_vertex;
    std::vector<Point2> points(n);
    std::vector<uint32_t> ids(n);
    std::vector<double> values(binned_.has_values ? n : 0);
    RETURN_IF_ERROR(
        points_.ReadItems(tile.first_vertex, std::span<Point2>(points)));
    RETURN_IF_ERROR(
        ids_.ReadItems(tile.first_vertex, std::span<uint32_t>(ids)));
    if (binned_.has_values) {
      RETURN_IF_ERROR(
          values_.ReadItems(tile.first_vertex, std::span<double>(values)));
    }
    for (const Point2& p : points) entry->bounds.Extend(p);
    entry->info.halo_points = triangles.halo_points;
    entry->info.rounds = static_cast<uint32_t>(triangles.rounds);
    return WriteTileFile(
        TileFilePath(dir_, entry->info.number), points, ids, values,
        std::span<const MeshTriangle>(triangles.triangles.data(),
                                      triangles.triangles.size()),
        &entry->info);
  }

 private:
  const std::string& dir_;
  const BinnedPoints& binned_;
  RandomAccessFile points_, ids_, values_;
  Status opened_;
};

// Whether an earlier run wrote `entry`'s tile for this build; fills its
// statistics from the file if so (the bounds from its points).
bool KeepWrittenTile(const std::string& dir,
                     TileSetManifest::TileEntry* entry) {
  TileFileInfo info;
  const std::string path = TileFilePath(dir, entry->info.number);
  if (!ReadTileFileInfo(path, &info).ok() ||
      info.build_key != entry->info.build_key ||
      info.number != entry->info.number || info.tile != entry->info.tile) {
    return false;
  }
  RandomAccessFile file;
  std::vector<Point2> points(info.tile.end_vertex - info.tile.first_vertex);
  // The points section starts right after the header.
  if (!file.Open(path).ok() || !file.ReadAt(kTileFileHeaderBytes, points.data(),
                                            points.size() * sizeof(Point2))
                                    .ok()) {
    return false;
  }
  for (const Point2& p : points) entry->bounds.Extend(p);
  entry->info = info;
  return true;
}

}  // namespace

std::string TileFilePath(const std::string& dir, size_t number) {
  char name[32];
  std::snprintf(name, sizeof(name), "/tile-%05zu.tile", number);
  return dir + name;
}

Status BuildTileSet(PointStream* stream, const TileSetSource& source,
                    const std::string& dir, const TileSetOptions& options,
                    const std::function<void(const TileSetProgress&)>& progress,
                    TileSetManifest* manifest, TileSetStats* stats) {
  TileSetStats local_stats;
  if (stats == nullptr) stats = &local_stats;
  const auto start = std::chrono::steady_clock::now();
  const unsigned threads = std::max(options.threads, 1u);
  const std::string work = dir + "/work";
  RETURN_IF_ERROR(MakeDirectory(dir));
  RETURN_IF_ERROR(MakeDirectory(work));

  TileSetProgress report;
  progress(report);
  const uint64_t bins_key =
      KeyOf({options.cell_points, kTileFileVersion}, source.key);
  BinnedPoints binned;
  RETURN_IF_ERROR(
      SortedPointsOf(stream, work, options, bins_key, &binned, stats));
  stats->bins = binned.bins;
  stats->bin_seconds = SecondsSince(start);

  const auto tiles_start = std::chrono::steady_clock::now();
  TileWriter writer(work, dir, binned);
  RETURN_IF_ERROR(writer.opened());
  HullEdges hull;
  RETURN_IF_ERROR(HullOf(binned, writer.points(), threads, &hull));
  const BinnedCellSource cells(binned, writer.points());
  const size_t tile_points =
      options.tile_points > 0
          ? options.tile_points
          : std::max(kMinTilePoints,
                     options.memory_bytes / (kTileBytesPerPoint * threads));
  const std::vector<Tile> tiles = CutTiles(binned.grid, cells, tile_points);

  TileSetManifest m;
  m.source = source.name;
  m.crs = source.crs;
  m.fingerprint = binned.fingerprint;
  m.build_key = KeyOf({bins_key, binned.fingerprint, tile_points}, "");
  m.input_points = binned.input_points;
  m.vertices = binned.vertices;
  m.has_values = binned.has_values;
  m.bounds = binned.grid.box();
  m.grid_level = binned.grid.level();
  m.hull = hull.ring();
  m.tiles.resize(tiles.size());
  report = {TileSetProgress::Stage::kTiles, 0, tiles.size(), 0,
            binned.vertices};
  std::vector<size_t> to_build;
  for (size_t t = 0; t < tiles.size(); ++t) {
    TileSetManifest::TileEntry& entry = m.tiles[t];
    entry.file = TileFilePath("", t).substr(1);
    entry.info.build_key = m.build_key;
    entry.info.number = static_cast<uint32_t>(t);
    entry.info.tile = tiles[t];
    if (KeepWrittenTile(dir, &entry)) {
      ++stats->tiles_reused;
      ++report.tiles_done;
      report.points_done += tiles[t].end_vertex - tiles[t].first_vertex;
    } else {
      to_build.push_back(t);
    }
  }
  progress(report);

  const TileContext context{binned.grid, cells, hull, binned.vertices};
  std::vector<Status> status(to_build.size());
  std::vector<std::unique_ptr<HaloCells>> halos(threads);
  std::mutex report_mu;
  ParallelTasks(to_build.size(), threads, [&](size_t k, size_t worker) {
    const size_t t = to_build[k];
    try {
      if (!halos[worker]) {
        halos[worker] = std::make_unique<HaloCells>(binned.grid, cells);
      }
      TileTriangles triangles;
      status[k] =
          TriangulateTile(context, tiles[t], halos[worker].get(), &triangles);
      if (status[k].ok()) status[k] = cells.error();
      if (status[k].ok()) status[k] = writer.Write(triangles, &m.tiles[t]);
    } catch (const std::bad_alloc&) {
      status[k] = Status::ResourceExhausted(
          "out of memory triangulating tile " + std::to_string(t) +
          "; a smaller --max-memory gives smaller tiles");
    } catch (const std::exception& e) {
      status[k] =
          Status::Internal("tile " + std::to_string(t) + ": " + e.what());
    }
    const std::lock_guard<std::mutex> lock(report_mu);
    ++report.tiles_done;
    report.points_done += tiles[t].end_vertex - tiles[t].first_vertex;
    progress(report);
  });
  for (const Status& s : status) RETURN_IF_ERROR(s);
  stats->tile_seconds = SecondsSince(tiles_start);

  const auto mesh_start = std::chrono::steady_clock::now();
  report.stage = TileSetProgress::Stage::kMesh;
  progress(report);
  m.mesh_file = MeshFilePath("", m.fingerprint);
  RETURN_IF_ERROR(WriteTileSetMesh(
      {dir, work, binned, m, options.memory_bytes / kMeshBytesPerTriangle},
      dir + "/" + m.mesh_file));
  stats->mesh_seconds = SecondsSince(mesh_start);

  m.build_seconds = SecondsSince(start);
  RETURN_IF_ERROR(
      WriteFileAtomically(dir + "/manifest.json", ManifestJson(m) + "\n"));
  for (const std::string& path :
       {BinnedPointsPath(work), BinnedIdsPath(work), BinnedValuesPath(work),
        InputPointsPath(work), work + "/bins.state"}) {
    std::remove(path.c_str());
  }
  ::rmdir(work.c_str());
  report.stage = TileSetProgress::Stage::kDone;
  progress(report);
  *manifest = std::move(m);
  return Status::OK();
}

}  // namespace locator
