// BuildTileSet: the canonical Delaunay triangulation of a plain point set
// of any size, built out of core into a directory of tile files and a
// manifest (tile_file.h, tileset_manifest.h), with bounded memory.
//
// Steps: BinPoints sorts the stream's distinct points to disk in the
// serving mesh's vertex order (point_bins.h); the hull of all of them
// comes from each bin's hull candidates; CutTiles cuts the cells into tiles
// of about tile_points vertices along the Hilbert curve; each tile is
// triangulated with a certified halo read from disk (TriangulateTile, as
// the in-memory tiled build) and written to "tile-NNNNN.tile";
// WriteTileSetMesh assembles them into the mesh file locatord maps
// ("mesh-<fingerprint>.mesh", tileset_mesh.h); last "manifest.json". The
// union of the tiles' triangles is exactly the canonical Delaunay
// triangulation of all the points, and the mesh file is byte for byte the
// one a build in memory (Triangulation::Build, BuildTiledMesh) writes.
//
// Resumable: the sorted points stay in DIR/work until the manifest is
// written, and a tile file already there for the same build is kept, so a
// killed build started again with the same source and options redoes only
// the tiles it had not written. Files are written atomically.
//
// Memory: about memory_bytes at the peak (bins of memory_bytes / 80
// points; tiles of memory_bytes / (800 threads) points unless tile_points
// says otherwise; triangle bins of memory_bytes / 100 triangles), plus 4
// bytes per grid cell (at most 4^12), per hull candidate and, while the
// mesh is assembled, per triangle. Disk: the tiles (about 68 bytes per
// point) and the mesh file (about 76) stay; the work files (about 110 bytes
// per point at the peak) are removed at the end.
//
// Thread-safety: a pure function; it starts and joins its own threads and
// calls `progress` from them, one call at a time.

#ifndef LOCATOR_CORE_TILESET_TILESET_BUILD_H_
#define LOCATOR_CORE_TILESET_TILESET_BUILD_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "locator/status.h"
#include "server/core/tileset/point_stream.h"
#include "server/core/tileset/tileset_manifest.h"

namespace locator {

struct TileSetOptions {
  unsigned threads = 1;
  // The peak memory to stay within, roughly (see above).
  size_t memory_bytes = size_t{4} << 30;
  // Vertices per tile; 0 picks one from memory_bytes and threads.
  size_t tile_points = 0;
  // Points per grid cell, on average: the grain of halos.
  size_t cell_points = 4;
};

// Where a build is, for a progress line.
struct TileSetProgress {
  enum class Stage { kBinning, kTiles, kMesh, kDone };
  Stage stage = Stage::kBinning;
  size_t tiles_done = 0;  // written or kept from an earlier run
  size_t tiles = 0;
  uint64_t points_done = 0;  // own vertices of the tiles done
  uint64_t points = 0;       // vertices in all
};

struct TileSetStats {
  bool bins_reused = false;  // the sorted points of an earlier run
  size_t bins = 0;
  size_t tiles_reused = 0;
  double bin_seconds = 0;
  double tile_seconds = 0;
  double mesh_seconds = 0;
};

// What a build is of: a description that differs whenever the points may
// (a generator's CanonicalKey(), a file's path, size and time), and the
// CRS to record.
struct TileSetSource {
  std::string key;
  std::string name;  // the spec, for the manifest
  std::string crs;
};

// Builds the tile set of `stream` into `dir` (created if missing) as
// described above, filling *manifest (also written to dir/manifest.json).
// InvalidArgument for points that cannot be triangulated (non-finite, fewer
// than 3 distinct, all collinear, too many); IOError naming the file that
// failed; ResourceExhausted if memory runs out; Internal if a tile cannot
// be certified (a bug, never a wrong tile).
[[nodiscard]] Status BuildTileSet(
    PointStream* stream, const TileSetSource& source, const std::string& dir,
    const TileSetOptions& options,
    const std::function<void(const TileSetProgress&)>& progress,
    TileSetManifest* manifest, TileSetStats* stats = nullptr);

// The path of tile number `number` in `dir`: "DIR/tile-NNNNN.tile".
std::string TileFilePath(const std::string& dir, size_t number);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_TILESET_BUILD_H_
