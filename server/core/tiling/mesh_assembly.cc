#include "server/core/tiling/mesh_assembly.h"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <utility>

#include "common/status_macros.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/radix_sort.h"
#include "server/core/tiling/build_checks.h"
#include "server/core/tiling/cells/parallel.h"
#include "server/core/tiling/mesh_vectors.h"
#include "server/core/tiling/open_edges.h"

namespace locator {

namespace {

constexpr uint32_t kOpen = TileTriangles::kOpen;

uint32_t EdgeStart(const MeshTriangle& t, int i) { return t.corner[Ccw(i)]; }
uint32_t EdgeEnd(const MeshTriangle& t, int i) { return t.corner[Cw(i)]; }

// The assembly's steps. Triangles stay in the tiles' lists until they are
// written into the mesh; a triangle's number is its tile's offset plus its
// index there.
class Assembly {
 public:
  Assembly(const SortedPoints& sorted, std::vector<TileTriangles>* tiles,
           unsigned threads);

  // Rotates each triangle so that corner 0 has the smallest public id,
  // turns neighbours into triangle numbers, and keys each triangle by its
  // centroid's Hilbert key.
  void Prepare();
  // Pairs the open edges; the unpaired ones are the hull, in ring order.
  Status MatchOpenEdges();
  // Orders the triangles and writes them into `storage`, freeing the
  // tiles' lists.
  void Order(MeshVectors* storage);
  // Marks the hull edges in ring order and checks Euler's formula.
  Status LinkHull(MeshVectors* storage);

 private:
  std::array<uint32_t, 3> CornerIds(const MeshTriangle& t) const {
    return {ids_[t.corner[0]], ids_[t.corner[1]], ids_[t.corner[2]]};
  }
  // Triangle number g, in its tile's list.
  MeshTriangle& Triangle(uint32_t g) {
    const size_t t = static_cast<size_t>(
        std::upper_bound(first_.begin(), first_.end(), g) - first_.begin() - 1);
    return tiles_[t].triangles[g - first_[t]];
  }

  const LargeVector<uint32_t>& ids_;
  const LargeVector<Point2>& points_;
  const BoundingBox box_;
  std::vector<TileTriangles>& tiles_;
  const unsigned threads_;
  // first_[t]: the number of tile t's first triangle (one entry per tile).
  std::vector<uint32_t> first_;
  size_t faces_ = 0;
  // (centroid key << 32 | triangle number), sorted by Order().
  LargeVector<uint64_t> items_;
  std::vector<OpenEdge> hull_;
  // position_[g]: where triangle number g goes in the mesh.
  LargeVector<uint32_t> position_;
};

Assembly::Assembly(const SortedPoints& sorted,
                   std::vector<TileTriangles>* tiles, unsigned threads)
    : ids_(sorted.ids),
      points_(sorted.points),
      box_(sorted.grid.box()),
      tiles_(*tiles),
      threads_(threads) {
  for (const TileTriangles& tile : tiles_) {
    first_.push_back(static_cast<uint32_t>(faces_));
    faces_ += tile.triangles.size();
  }
}

void Assembly::Prepare() {
  items_.resize(faces_);
  ParallelTasks(tiles_.size(), threads_, [&](size_t t, size_t) {
    const uint32_t offset = first_[t];
    LargeVector<MeshTriangle>& own = tiles_[t].triangles;
    for (size_t k = 0; k < own.size(); ++k) {
      const MeshTriangle m = own[k];
      const std::array<uint32_t, 3> ids = CornerIds(m);
      const int r = static_cast<int>(std::min_element(ids.begin(), ids.end()) -
                                     ids.begin());
      MeshTriangle& out = own[k];
      for (int i = 0; i < 3; ++i) {
        const int from = (i + r) % 3;  // edge i stays opposite corner i
        out.corner[i] = m.corner[from];
        out.neighbor[i] =
            m.neighbor[from] == kOpen ? kOpen : m.neighbor[from] + offset;
      }
      const uint32_t key = ServingMesh::CentroidKey(
          points_[out.corner[0]], points_[out.corner[1]],
          points_[out.corner[2]], box_);
      items_[offset + k] = uint64_t{key} << 32 | (offset + k);
    }
  });
}

Status Assembly::MatchOpenEdges() {
  std::vector<std::vector<OpenEdge>> per_tile(tiles_.size());
  ParallelTasks(tiles_.size(), threads_, [&](size_t t, size_t) {
    const LargeVector<MeshTriangle>& own = tiles_[t].triangles;
    for (size_t k = 0; k < own.size(); ++k) {
      for (uint32_t i = 0; i < 3; ++i) {
        if (own[k].neighbor[i] != kOpen) continue;
        per_tile[t].push_back({static_cast<uint32_t>(first_[t] + k), i,
                               EdgeStart(own[k], static_cast<int>(i)),
                               EdgeEnd(own[k], static_cast<int>(i))});
      }
    }
  });
  std::vector<OpenEdge> open;
  for (std::vector<OpenEdge>& part : per_tile) {
    open.insert(open.end(), part.begin(), part.end());
    std::vector<OpenEdge>().swap(part);
  }
  std::vector<std::array<OpenEdge, 2>> pairs;
  RETURN_IF_ERROR(locator::MatchOpenEdges(
      "tiled build", std::move(open),
      [this](uint32_t vertex, uint32_t* id) {
        *id = ids_[vertex];
        return Status::OK();
      },
      &pairs, &hull_));
  for (const auto& [e, g] : pairs) {
    Triangle(e.face).neighbor[e.edge] = g.face;
    Triangle(g.face).neighbor[g.edge] = e.face;
  }
  return Status::OK();
}

void Assembly::Order(MeshVectors* storage) {
  SortByHighHalf(&items_);
  // Equal keys: by the corners' public ids.
  for (size_t k = 0; k < faces_;) {
    size_t end = k + 1;
    while (end < faces_ && (items_[end] >> 32) == (items_[k] >> 32)) ++end;
    if (end - k > 1) {
      std::sort(items_.begin() + k, items_.begin() + end,
                [&](uint64_t a, uint64_t b) {
                  return CornerIds(Triangle(static_cast<uint32_t>(a))) <
                         CornerIds(Triangle(static_cast<uint32_t>(b)));
                });
    }
    k = end;
  }
  position_.resize(faces_);
  for (size_t k = 0; k < faces_; ++k) {
    position_[static_cast<uint32_t>(items_[k])] = static_cast<uint32_t>(k);
  }
  storage->triangles.resize(faces_);
  ParallelSlices(faces_, threads_, [&](size_t begin, size_t end, size_t) {
    for (size_t k = begin; k < end; ++k) {
      MeshTriangle m = Triangle(static_cast<uint32_t>(items_[k]));
      for (uint32_t& n : m.neighbor) {
        if (n != kOpen) n = position_[n];
      }
      storage->triangles[k] = m;
    }
  });
  LargeVector<uint64_t>().swap(items_);
  for (TileTriangles& tile : tiles_) {
    LargeVector<MeshTriangle>().swap(tile.triangles);
  }
}

Status Assembly::LinkHull(MeshVectors* storage) {
  LargeVector<MeshTriangle>& triangles = storage->triangles;
  storage->hull.reserve(hull_.size());
  for (size_t n = 0; n < hull_.size(); ++n) {
    const uint32_t face = position_[hull_[n].face];
    triangles[face].neighbor[hull_[n].edge] =
        ServingMesh::kHullBit | static_cast<uint32_t>(n);
    storage->hull.push_back(
        ServingMesh::Edge(face, static_cast<int>(hull_[n].edge)));
  }
  return CheckEulerFormula("tiled build", points_.size(), triangles.size(),
                           hull_.size());
}

}  // namespace

Status AssembleServingMesh(SortedPoints* sorted,
                           std::vector<TileTriangles>* tiles,
                           std::span<const double> values, uint64_t digest,
                           unsigned threads,
                           std::shared_ptr<const ServingMesh>* out) {
  size_t faces = 0;
  for (const TileTriangles& tile : *tiles) faces += tile.triangles.size();
  RETURN_IF_ERROR(CheckMeshSize(sorted->size(), faces));
  auto storage = std::make_unique<MeshVectors>();
  Assembly assembly(*sorted, tiles, threads);
  assembly.Prepare();
  RETURN_IF_ERROR(assembly.MatchOpenEdges());
  assembly.Order(storage.get());
  RETURN_IF_ERROR(assembly.LinkHull(storage.get()));
  if (!values.empty()) {
    storage->values.resize(sorted->size());
    for (size_t v = 0; v < sorted->size(); ++v) {
      storage->values[v] = values[sorted->ids[v]];
    }
  }
  storage->points = std::move(sorted->points);
  storage->ids = std::move(sorted->ids);
  ServingMesh::Arrays arrays = storage->Views();
  arrays.in_domain = static_cast<uint32_t>(faces);
  arrays.box = sorted->grid.box();
  arrays.input_points = sorted->input_points;
  arrays.digest = digest;
  *out = std::make_shared<const ServingMesh>(std::move(storage), arrays);
  return Status::OK();
}

void AddDistinctVertices(std::span<const Point2> points, uint64_t first,
                         const std::vector<bool>& distinct, Xxh3Digest* hash) {
  for (size_t k = 0; k < points.size(); ++k) {
    if (!distinct[first + k]) continue;
    hash->AddU64(first + k);
    hash->AddDouble(points[k].x);
    hash->AddDouble(points[k].y);
  }
}

uint64_t VertexDigestOf(std::span<const Point2> input,
                        std::span<const uint32_t> ids) {
  std::vector<bool> distinct(input.size(), false);
  for (const uint32_t id : ids) distinct[id] = true;
  Xxh3Digest hash;
  AddDistinctVertices(input, 0, distinct, &hash);
  return hash.digest();
}

}  // namespace locator
