// BinPoints: the out-of-core sort of the tile-set build. It streams a
// point set to disk and leaves its distinct points in the serving mesh's
// vertex order (SortedPoints' order: by cell of a CellGrid along the
// Hilbert curve, then fine key, then input index; repeats merged into the
// first), without holding more than a bin of points in memory:
//   1. the stream is read once into "input.points" (and "input.values"),
//      finding the bounding box and the count;
//   2. that copy is read to count the points of every cell and to take the
//      dataset's fingerprint (DatasetFingerprint of the same points);
//   3. read again, each point goes to the bin of its cell: bins are ranges
//      of cells of about `bin_points` points;
//   4. each bin in turn is sorted and its repeats merged in memory, and
//      appended to "points.bin", "ids.bin" (input indices) and "values.bin".
// "input.points" stays (the mesh digest reads the points in input order);
// "input.values" and the bins are removed. The state (grid, cell offsets,
// counts, hull candidates) goes to "bins.state", so that a build killed
// later resumes without binning again.
//
// Thread-safety: free functions; BinnedCellSource allows concurrent reads.

#ifndef LOCATOR_CORE_TILESET_POINT_BINS_H_
#define LOCATOR_CORE_TILESET_POINT_BINS_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/mutex.h"
#include "common/thread_annotations.h"
#include "locator/status.h"
#include "server/core/tileset/binary_files.h"
#include "server/core/tileset/point_stream.h"
#include "server/core/tiling/cells/cell_grid.h"
#include "server/core/tiling/cells/cell_source.h"

namespace locator {

struct BinningOptions {
  // Points per grid cell, on average (TiledBuildOptions::cell_points).
  size_t cell_points = 4;
  // The most points sorted in memory at once.
  size_t bin_points = size_t{1} << 24;
  // Bytes buffered per open bin file while scattering.
  size_t buffer_bytes = size_t{1} << 20;
};

struct BinnedPoints {
  CellGrid grid{BoundingBox{0, 0, 1, 1}, 0};
  // cell_start[c] .. cell_start[c + 1] are the vertices of cell c.
  std::vector<uint32_t> cell_start;
  uint64_t input_points = 0;
  uint64_t vertices = 0;
  bool has_values = false;
  // DatasetFingerprint of the points (and values) as streamed.
  uint64_t fingerprint = 0;
  // Vertices that may lie on the hull of all of them, increasing: every
  // vertex on it is among them.
  std::vector<uint32_t> hull_candidates;
  // Bins the points were sorted in.
  size_t bins = 0;
};

// The first cell of each of the ranges that cut the cells, along the
// curve, into runs of at most `max_weight` (or one cell, if it alone
// weighs more): the bins of points (weight: points per cell) or of
// triangles.
std::vector<uint32_t> CutCellRanges(std::span<const uint64_t> cell_weights,
                                    uint64_t max_weight);

// The files BinPoints leaves in `dir`.
std::string BinnedPointsPath(const std::string& dir);  // "points.bin"
std::string BinnedIdsPath(const std::string& dir);     // "ids.bin"
std::string BinnedValuesPath(const std::string& dir);  // "values.bin"
// The input points as streamed, kept for the mesh's digest.
std::string InputPointsPath(const std::string& dir);  // "input.points"

// Sorts the points of `stream` into `dir` (an existing directory) as
// described above, recording `key` (what the source is) in the state.
// InvalidArgument naming the first point with a non-finite coordinate, or
// if there are more than ServingMesh::kMaxElements points or none;
// IOError naming the file that failed.
[[nodiscard]] Status BinPoints(PointStream* stream, const std::string& dir,
                               const BinningOptions& options, uint64_t key,
                               BinnedPoints* out);

// Reads the state an earlier BinPoints left in `dir` for `key`. NotFound
// if there is none or it was made for another key (or is damaged), so
// that the caller bins again.
[[nodiscard]] Status LoadBinnedPoints(const std::string& dir, uint64_t key,
                                      BinnedPoints* out);

// The cells of binned points, read from "points.bin" as tiles ask.
class BinnedCellSource : public CellSource {
 public:
  // Reads through `points` ("points.bin", open); both must outlive it.
  BinnedCellSource(const BinnedPoints& binned, const RandomAccessFile& points)
      : binned_(binned), points_(points) {}
  uint32_t CellSize(uint32_t cell) const override {
    return binned_.cell_start[cell + 1] - binned_.cell_start[cell];
  }
  uint32_t CellStart(uint32_t cell) const override {
    return binned_.cell_start[cell];
  }
  // A read that fails leaves the cell out and is kept for error().
  void ReadCell(uint32_t cell, std::vector<TileVertex>* out) const override;
  // OK, or the first read that failed: a tile that read its cells while
  // this was not OK is not to be trusted.
  Status error() const EXCLUDES(mu_);

 private:
  const BinnedPoints& binned_;
  const RandomAccessFile& points_;
  mutable Mutex mu_;
  mutable Status error_ GUARDED_BY(mu_);
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_POINT_BINS_H_
