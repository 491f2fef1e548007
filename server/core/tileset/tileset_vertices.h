// The vertex data the tile-set mesh assembly reads (tileset_mesh.h): one
// vertex at a time from the sorted points' files (VertexFiles), a tile's
// corners at once (TileVertices: its own vertices from its file, the halo's
// from the sorted points), and the mesh digest of all of them.
//
// Thread-safety: VertexFiles' reads may run concurrently; a TileVertices
// on one thread.

#ifndef LOCATOR_CORE_TILESET_TILESET_VERTICES_H_
#define LOCATOR_CORE_TILESET_TILESET_VERTICES_H_

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/core/tileset/binary_files.h"
#include "server/core/tileset/point_bins.h"
#include "server/core/tileset/tile_file.h"

namespace locator {

class VertexFiles {
 public:
  // Opens BinPoints' points and ids files in `work`.
  [[nodiscard]] Status Open(const std::string& work);
  [[nodiscard]] Status ReadPoint(uint32_t vertex, Point2* point) const {
    return points_.ReadItems(vertex, std::span<Point2>(point, 1));
  }
  [[nodiscard]] Status ReadId(uint32_t vertex, uint32_t* id) const {
    return ids_.ReadItems(vertex, std::span<uint32_t>(id, 1));
  }

 private:
  RandomAccessFile points_, ids_;
};

class TileVertices {
 public:
  // Reads and checks the tile file at `path` (DecodeTileFile), and the
  // corners of its triangles that other tiles own from `vertices`.
  [[nodiscard]] Status Load(const std::string& path,
                            const VertexFiles& vertices);
  std::span<const MeshTriangle> triangles() const { return arrays_.triangles; }
  // Precondition: `vertex` is a corner of one of triangles().
  uint32_t Id(uint32_t vertex) const;
  const Point2& Point(uint32_t vertex) const;

 private:
  // The index of `vertex` among the halo corners.
  size_t HaloIndex(uint32_t vertex) const;

  std::string bytes_;
  TileFileInfo info_;
  TileFileArrays arrays_;
  std::vector<uint32_t> halo_;  // sorted
  std::vector<Point2> halo_points_;
  std::vector<uint32_t> halo_ids_;
};

// Triangulation::VertexDigest() of the binned points (XXH3 over the id, x
// and y of each distinct point, in id order), from the input copy and the
// ids BinPoints left in `work`.
StatusOr<uint64_t> VertexDigestOfFiles(const std::string& work,
                                       const BinnedPoints& binned);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_TILESET_VERTICES_H_
