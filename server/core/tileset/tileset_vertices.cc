#include "server/core/tileset/tileset_vertices.h"

#include <algorithm>

#include "common/status_macros.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/tiling/mesh_assembly.h"

namespace locator {

namespace {
constexpr uint64_t kChunk = uint64_t{1} << 20;
}  // namespace

Status VertexFiles::Open(const std::string& work) {
  RETURN_IF_ERROR(points_.Open(BinnedPointsPath(work)));
  return ids_.Open(BinnedIdsPath(work));
}

Status TileVertices::Load(const std::string& path,
                          const VertexFiles& vertices) {
  RETURN_IF_ERROR(ReadWholeFile(path, "tile", &bytes_));
  const Status decoded = DecodeTileFile(bytes_, &info_, &arrays_);
  if (!decoded.ok()) {
    return Status::InvalidArgument(path + ": " + decoded.message());
  }
  halo_.clear();
  for (const MeshTriangle& t : arrays_.triangles) {
    for (const uint32_t v : t.corner) {
      if (v < info_.tile.first_vertex || v >= info_.tile.end_vertex) {
        halo_.push_back(v);
      }
    }
  }
  std::sort(halo_.begin(), halo_.end());
  halo_.erase(std::unique(halo_.begin(), halo_.end()), halo_.end());
  halo_points_.resize(halo_.size());
  halo_ids_.resize(halo_.size());
  for (size_t k = 0; k < halo_.size(); ++k) {
    RETURN_IF_ERROR(vertices.ReadPoint(halo_[k], &halo_points_[k]));
    RETURN_IF_ERROR(vertices.ReadId(halo_[k], &halo_ids_[k]));
  }
  return Status::OK();
}

size_t TileVertices::HaloIndex(uint32_t vertex) const {
  return std::lower_bound(halo_.begin(), halo_.end(), vertex) - halo_.begin();
}

uint32_t TileVertices::Id(uint32_t vertex) const {
  if (vertex >= info_.tile.first_vertex && vertex < info_.tile.end_vertex) {
    return arrays_.ids[vertex - info_.tile.first_vertex];
  }
  return halo_ids_[HaloIndex(vertex)];
}

const Point2& TileVertices::Point(uint32_t vertex) const {
  if (vertex >= info_.tile.first_vertex && vertex < info_.tile.end_vertex) {
    return arrays_.points[vertex - info_.tile.first_vertex];
  }
  return halo_points_[HaloIndex(vertex)];
}

StatusOr<uint64_t> VertexDigestOfFiles(const std::string& work,
                                       const BinnedPoints& binned) {
  std::vector<bool> distinct(binned.input_points, false);
  RandomAccessFile ids, input;
  RETURN_IF_ERROR(ids.Open(BinnedIdsPath(work)));
  RETURN_IF_ERROR(input.Open(InputPointsPath(work)));
  std::vector<uint32_t> id_chunk;
  for (uint64_t first = 0; first < binned.vertices; first += id_chunk.size()) {
    id_chunk.resize(std::min(kChunk, binned.vertices - first));
    RETURN_IF_ERROR(ids.ReadItems(first, std::span<uint32_t>(id_chunk)));
    for (const uint32_t id : id_chunk) distinct[id] = true;
  }
  Xxh3Digest digest;
  std::vector<Point2> chunk;
  for (uint64_t first = 0; first < binned.input_points; first += chunk.size()) {
    chunk.resize(std::min(kChunk, binned.input_points - first));
    RETURN_IF_ERROR(input.ReadItems(first, std::span<Point2>(chunk)));
    AddDistinctVertices(chunk, first, distinct, &digest);
  }
  return digest.digest();
}

}  // namespace locator
