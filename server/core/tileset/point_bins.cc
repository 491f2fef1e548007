#include "server/core/tileset/point_bins.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <utility>

#include "common/status_macros.h"
#include "server/core/dataset/dataset_fingerprint.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/mesh/radix_sort.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tileset/bins_state.h"
#include "server/core/tiling/cells/sorted_points.h"
#include "server/core/tiling/hull_edges.h"

namespace locator {
namespace {

constexpr size_t kChunkPoints = size_t{1} << 20;
// A bin with at most this many distinct points sends them all to the hull
// candidates (HullEdges needs three points off one line).
constexpr size_t kAllCandidates = 16;

std::string InputValuesPath(const std::string& dir) {
  return dir + "/input.values";
}
std::string BinPath(const std::string& dir, size_t bin, const char* kind) {
  return dir + "/bin-" + std::to_string(bin) + "." + kind;
}

// A point in a bin file: its fine key, its input index and itself.
struct BinRecord {
  uint32_t key;
  uint32_t id;
  Point2 point;
};
static_assert(sizeof(BinRecord) == 24);

// Reads an array of T from `path` in chunks, calling visit(first, chunk).
template <class T, class Visit>
Status ForEachChunk(const std::string& path, uint64_t count, Visit visit) {
  RandomAccessFile file;
  RETURN_IF_ERROR(file.Open(path));
  std::vector<T> chunk;
  for (uint64_t first = 0; first < count; first += chunk.size()) {
    chunk.resize(std::min<uint64_t>(kChunkPoints, count - first));
    RETURN_IF_ERROR(file.ReadItems(first, std::span<T>(chunk)));
    RETURN_IF_ERROR(visit(first, std::span<const T>(chunk)));
  }
  return Status::OK();
}

// Step 1: the stream's points to input.points/.values; box and count.
Status CopyInput(PointStream* stream, const std::string& dir,
                 const BinningOptions& options, BoundingBox* box,
                 uint64_t* count) {
  RETURN_IF_ERROR(stream->Rewind());
  AppendFile points, values;
  RETURN_IF_ERROR(points.Create(InputPointsPath(dir), options.buffer_bytes));
  if (stream->has_values()) {
    RETURN_IF_ERROR(values.Create(InputValuesPath(dir), options.buffer_bytes));
  }
  std::vector<Point2> chunk;
  std::vector<double> chunk_values;
  *count = 0;
  for (;;) {
    RETURN_IF_ERROR(stream->Read(kChunkPoints, &chunk, &chunk_values));
    if (chunk.empty()) break;
    for (size_t i = 0; i < chunk.size(); ++i) {
      if (!std::isfinite(chunk[i].x) || !std::isfinite(chunk[i].y)) {
        return Status::InvalidArgument("point " + std::to_string(*count + i) +
                                       " has a non-finite coordinate");
      }
      box->Extend(chunk[i]);
    }
    *count += chunk.size();
    if (*count > ServingMesh::kMaxElements) {
      return Status::InvalidArgument("the source has more than " +
                                     std::to_string(ServingMesh::kMaxElements) +
                                     " points, the most a tile set numbers");
    }
    RETURN_IF_ERROR(points.Append(std::span<const Point2>(chunk)));
    if (stream->has_values()) {
      RETURN_IF_ERROR(values.Append(std::span<const double>(chunk_values)));
    }
  }
  if (*count == 0) return Status::InvalidArgument("the source has no points");
  RETURN_IF_ERROR(points.Close());
  return stream->has_values() ? values.Close() : Status::OK();
}

// Step 2: points per cell, and the fingerprint.
Status CountCells(const std::string& dir, BinnedPoints* out,
                  std::vector<uint64_t>* cell_points) {
  PointSetFingerprint fingerprint;
  fingerprint.Begin(out->input_points);
  cell_points->assign(out->grid.num_cells(), 0);
  RETURN_IF_ERROR(ForEachChunk<Point2>(
      InputPointsPath(dir), out->input_points,
      [&](uint64_t, std::span<const Point2> chunk) {
        fingerprint.AddPoints(chunk);
        for (const Point2& p : chunk) {
          ++(*cell_points)[out->grid.CellOfKey(out->grid.FineKey(p))];
        }
        return Status::OK();
      }));
  fingerprint.Begin(out->has_values ? out->input_points : 0);
  if (out->has_values) {
    RETURN_IF_ERROR(
        ForEachChunk<double>(InputValuesPath(dir), out->input_points,
                             [&](uint64_t, std::span<const double> chunk) {
                               fingerprint.AddValues(chunk);
                               return Status::OK();
                             }));
  }
  out->fingerprint = fingerprint.Finish();
  return Status::OK();
}

// Step 3: every point to its bin's files.
Status Scatter(const std::string& dir, const BinningOptions& options,
               const BinnedPoints& binned,
               const std::vector<uint32_t>& first_cells) {
  const size_t bins = first_cells.size();
  std::vector<std::unique_ptr<AppendFile>> records(bins), values(bins);
  for (size_t b = 0; b < bins; ++b) {
    records[b] = std::make_unique<AppendFile>();
    RETURN_IF_ERROR(
        records[b]->Create(BinPath(dir, b, "records"), options.buffer_bytes));
    if (binned.has_values) {
      values[b] = std::make_unique<AppendFile>();
      RETURN_IF_ERROR(
          values[b]->Create(BinPath(dir, b, "values"), options.buffer_bytes));
    }
  }
  RandomAccessFile input_values;
  if (binned.has_values)
    RETURN_IF_ERROR(input_values.Open(InputValuesPath(dir)));
  std::vector<double> chunk_values;
  RETURN_IF_ERROR(ForEachChunk<Point2>(
      InputPointsPath(dir), binned.input_points,
      [&](uint64_t first, std::span<const Point2> chunk) -> Status {
        if (binned.has_values) {
          chunk_values.resize(chunk.size());
          RETURN_IF_ERROR(
              input_values.ReadItems(first, std::span<double>(chunk_values)));
        }
        for (size_t i = 0; i < chunk.size(); ++i) {
          const uint32_t key = binned.grid.FineKey(chunk[i]);
          const size_t bin =
              std::upper_bound(first_cells.begin(), first_cells.end(),
                               binned.grid.CellOfKey(key)) -
              first_cells.begin() - 1;
          const BinRecord record{key, static_cast<uint32_t>(first + i),
                                 chunk[i]};
          RETURN_IF_ERROR(records[bin]->AppendBytes(&record, sizeof(record)));
          if (binned.has_values) {
            RETURN_IF_ERROR(
                values[bin]->AppendBytes(&chunk_values[i], sizeof(double)));
          }
        }
        return Status::OK();
      }));
  for (size_t b = 0; b < bins; ++b) {
    RETURN_IF_ERROR(records[b]->Close());
    if (binned.has_values) RETURN_IF_ERROR(values[b]->Close());
  }
  return Status::OK();
}

// The output files of step 4.
struct SortedVertexOutput {
  AppendFile points, ids, values;
};

// Step 4 for one bin: sorted, repeats merged, appended to the vertex files.
Status SortBin(const std::string& dir, size_t bin, BinnedPoints* binned,
               SortedVertexOutput* files) {
  RandomAccessFile record_file;
  RETURN_IF_ERROR(record_file.Open(BinPath(dir, bin, "records")));
  const size_t count = record_file.size() / sizeof(BinRecord);
  LargeVector<BinRecord> records(count);
  RETURN_IF_ERROR(record_file.ReadItems(0, std::span<BinRecord>(records)));
  std::vector<Point2> input(count);
  LargeVector<uint64_t> items(count);
  for (size_t i = 0; i < count; ++i) {
    input[i] = records[i].point;
    items[i] = uint64_t{records[i].key} << 32 | i;
  }
  SortByHighHalf(&items);
  LargeVector<Point2> points;
  LargeVector<uint32_t> local;
  points.reserve(count);
  local.reserve(count);
  AppendDistinct(items, input, binned->grid, &points, &local,
                 std::span<uint32_t>(binned->cell_start).subspan(1));
  const uint64_t first_vertex = binned->vertices;
  binned->vertices += points.size();

  std::vector<uint32_t> ids(local.size());
  for (size_t v = 0; v < local.size(); ++v) ids[v] = records[local[v]].id;
  RETURN_IF_ERROR(files->points.Append(std::span<const Point2>(points)));
  RETURN_IF_ERROR(files->ids.Append(std::span<const uint32_t>(ids)));
  if (binned->has_values) {
    RandomAccessFile value_file;
    RETURN_IF_ERROR(value_file.Open(BinPath(dir, bin, "values")));
    std::vector<double> values(count);
    RETURN_IF_ERROR(value_file.ReadItems(0, std::span<double>(values)));
    std::vector<double> vertex_values(local.size());
    for (size_t v = 0; v < local.size(); ++v)
      vertex_values[v] = values[local[v]];
    RETURN_IF_ERROR(
        files->values.Append(std::span<const double>(vertex_values)));
  }

  if (points.size() <= kAllCandidates) {
    for (size_t v = 0; v < points.size(); ++v) {
      binned->hull_candidates.push_back(
          static_cast<uint32_t>(first_vertex + v));
    }
  } else {
    std::vector<uint32_t> ring =
        HullEdges::Compute(points, /*threads=*/1).ring();
    std::sort(ring.begin(), ring.end());
    for (const uint32_t v : ring) {
      binned->hull_candidates.push_back(
          static_cast<uint32_t>(first_vertex + v));
    }
  }
  std::remove(BinPath(dir, bin, "records").c_str());
  std::remove(BinPath(dir, bin, "values").c_str());
  return Status::OK();
}

}  // namespace

std::string BinnedPointsPath(const std::string& dir) {
  return dir + "/points.bin";
}
std::string BinnedIdsPath(const std::string& dir) { return dir + "/ids.bin"; }
std::string InputPointsPath(const std::string& dir) {
  return dir + "/input.points";
}

std::vector<uint32_t> CutCellRanges(std::span<const uint64_t> cell_weights,
                                    uint64_t max_weight) {
  std::vector<uint32_t> first_cells{0};
  uint64_t in_range = 0;
  for (uint32_t cell = 0; cell < cell_weights.size(); ++cell) {
    if (in_range > 0 && in_range + cell_weights[cell] > max_weight) {
      first_cells.push_back(cell);
      in_range = 0;
    }
    in_range += cell_weights[cell];
  }
  return first_cells;
}
std::string BinnedValuesPath(const std::string& dir) {
  return dir + "/values.bin";
}

Status BinPoints(PointStream* stream, const std::string& dir,
                 const BinningOptions& options, uint64_t key,
                 BinnedPoints* out) {
  BinnedPoints binned;
  binned.has_values = stream->has_values();
  BoundingBox box;
  RETURN_IF_ERROR(CopyInput(stream, dir, options, &box, &binned.input_points));
  binned.grid = CellGrid(
      box, CellGrid::LevelFor(binned.input_points,
                              std::max<size_t>(options.cell_points, 1)));
  std::vector<uint64_t> cell_points;
  RETURN_IF_ERROR(CountCells(dir, &binned, &cell_points));
  const std::vector<uint32_t> first_cells =
      CutCellRanges(cell_points, std::max<size_t>(options.bin_points, 1));
  binned.bins = first_cells.size();
  RETURN_IF_ERROR(Scatter(dir, options, binned, first_cells));
  std::remove(InputValuesPath(dir).c_str());

  binned.cell_start.assign(binned.grid.num_cells() + 1, 0);
  SortedVertexOutput files;
  RETURN_IF_ERROR(
      files.points.Create(BinnedPointsPath(dir), options.buffer_bytes));
  RETURN_IF_ERROR(files.ids.Create(BinnedIdsPath(dir), options.buffer_bytes));
  if (binned.has_values) {
    RETURN_IF_ERROR(
        files.values.Create(BinnedValuesPath(dir), options.buffer_bytes));
  }
  for (size_t b = 0; b < first_cells.size(); ++b) {
    RETURN_IF_ERROR(SortBin(dir, b, &binned, &files));
  }
  RETURN_IF_ERROR(files.points.Close());
  RETURN_IF_ERROR(files.ids.Close());
  if (binned.has_values) RETURN_IF_ERROR(files.values.Close());
  for (size_t c = 1; c < binned.cell_start.size(); ++c) {
    binned.cell_start[c] += binned.cell_start[c - 1];
  }
  RETURN_IF_ERROR(SaveBinsState(dir, key, binned));
  *out = std::move(binned);
  return Status::OK();
}

Status LoadBinnedPoints(const std::string& dir, uint64_t key,
                        BinnedPoints* out) {
  return LoadBinsState(dir, key, out);
}

void BinnedCellSource::ReadCell(uint32_t cell,
                                std::vector<TileVertex>* out) const {
  const uint32_t first = binned_.cell_start[cell];
  const uint32_t size = CellSize(cell);
  std::vector<Point2> points(size);
  const Status read = points_.ReadItems(first, std::span<Point2>(points));
  if (!read.ok()) {
    MutexLock lock(&mu_);
    if (error_.ok()) error_ = read;
    return;
  }
  for (uint32_t k = 0; k < size; ++k) {
    out->push_back(TileVertex{points[k], first + k});
  }
}

Status BinnedCellSource::error() const {
  MutexLock lock(&mu_);
  return error_;
}

}  // namespace locator
