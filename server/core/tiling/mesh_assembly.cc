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

namespace locator {

namespace {

constexpr uint32_t kOpen = TileTriangles::kOpen;

// A hull edge or an edge between two tiles' triangles: edge `edge` of
// triangle `face`, keyed by its ends.
struct OpenEdge {
  uint64_t ends;  // smaller vertex << 32 | larger vertex
  uint32_t face;
  int edge;
};

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
  // Pairs the open edges; the unpaired ones are the hull.
  Status MatchOpenEdges();
  // Orders the triangles and writes them into `storage`, freeing the
  // tiles' lists.
  void Order(MeshVectors* storage);
  // Links the hull ring and checks Euler's formula.
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
      for (int i = 0; i < 3; ++i) {
        if (own[k].neighbor[i] != kOpen) continue;
        const uint32_t start = EdgeStart(own[k], i);
        const uint32_t end = EdgeEnd(own[k], i);
        per_tile[t].push_back(
            {uint64_t{std::min(start, end)} << 32 | std::max(start, end),
             static_cast<uint32_t>(first_[t] + k), i});
      }
    }
  });
  std::vector<OpenEdge> open;
  for (std::vector<OpenEdge>& part : per_tile) {
    open.insert(open.end(), part.begin(), part.end());
    std::vector<OpenEdge>().swap(part);
  }
  std::sort(open.begin(), open.end(), [](const OpenEdge& x, const OpenEdge& y) {
    return std::tie(x.ends, x.face, x.edge) < std::tie(y.ends, y.face, y.edge);
  });
  for (size_t k = 0; k < open.size();) {
    const OpenEdge& e = open[k];
    const size_t same =
        k + 1 < open.size() && open[k + 1].ends == e.ends ? 2 : 1;
    const std::string name = "edge " + std::to_string(e.ends >> 32) + "-" +
                             std::to_string(e.ends & 0xffffffffu);
    if (k + 2 < open.size() && open[k + 2].ends == e.ends) {
      return Status::Internal("tiled build: " + name +
                              " borders more than two triangles");
    }
    if (same == 1) {
      hull_.push_back(e);
      ++k;
      continue;
    }
    const OpenEdge& g = open[k + 1];
    MeshTriangle& ft = Triangle(e.face);
    MeshTriangle& gt = Triangle(g.face);
    if (EdgeStart(ft, e.edge) != EdgeEnd(gt, g.edge)) {
      return Status::Internal("tiled build: the two triangles of " + name +
                              " overlap");
    }
    ft.neighbor[e.edge] = g.face;
    gt.neighbor[g.edge] = e.face;
    k += 2;
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
  const size_t h = hull_.size();
  // (end vertex, hull_ index), to find the edge that ends where one starts.
  std::vector<std::pair<uint32_t, uint32_t>> by_end(h);
  size_t start = 0;
  for (size_t k = 0; k < h; ++k) {
    OpenEdge& e = hull_[k];
    e.face = position_[e.face];
    by_end[k] = {EdgeEnd(triangles[e.face], e.edge), static_cast<uint32_t>(k)};
    if (ids_[by_end[k].first] < ids_[by_end[start].first]) start = k;
  }
  std::sort(by_end.begin(), by_end.end());
  for (size_t k = 1; k < h; ++k) {
    if (by_end[k].first == by_end[k - 1].first) {
      return Status::Internal("tiled build: hull vertex " +
                              std::to_string(by_end[k].first) +
                              " ends two hull edges");
    }
  }
  storage->hull.reserve(h);
  size_t k = start;
  for (size_t n = 0; n < h; ++n) {
    if (n > 0 && k == start) {
      return Status::Internal("tiled build: the hull is more than one ring");
    }
    const OpenEdge& e = hull_[k];
    triangles[e.face].neighbor[e.edge] =
        ServingMesh::kHullBit | static_cast<uint32_t>(n);
    storage->hull.push_back(ServingMesh::Edge(e.face, e.edge));
    // The ring runs as ServingMesh's: the next edge ends where this starts.
    const uint32_t s = EdgeStart(triangles[e.face], e.edge);
    const auto next = std::lower_bound(by_end.begin(), by_end.end(),
                                       std::pair<uint32_t, uint32_t>{s, 0});
    if (next == by_end.end() || next->first != s) {
      return Status::Internal("tiled build: the hull is not closed at vertex " +
                              std::to_string(s));
    }
    k = next->second;
  }
  if (k != start) {
    return Status::Internal("tiled build: the hull is not one closed ring");
  }
  // Euler's formula for a triangulated point set: V - E + (F + 1) = 2,
  // with 2E = 3F + H.
  const size_t v = points_.size();
  const size_t f = triangles.size();
  if (2 * v != f + h + 2) {
    return Status::Internal("tiled build: " + std::to_string(v) +
                            " vertices, " + std::to_string(f) +
                            " triangles and " + std::to_string(h) +
                            " hull edges break Euler's formula");
  }
  return Status::OK();
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

uint64_t VertexDigestOf(std::span<const Point2> input,
                        std::span<const uint32_t> ids) {
  std::vector<bool> distinct(input.size(), false);
  for (const uint32_t id : ids) distinct[id] = true;
  Xxh3Digest hash;
  for (size_t id = 0; id < input.size(); ++id) {
    if (!distinct[id]) continue;
    hash.AddU64(id);
    hash.AddDouble(input[id].x);
    hash.AddDouble(input[id].y);
  }
  return hash.digest();
}

}  // namespace locator
