// GivenMeshBuilder: the steps of BuildGivenMesh (given_mesh.h). Internal to
// given_mesh_check.cc (the points, the triangles and their edges, the
// boundary's triangulation and which of its faces are inside) and
// given_mesh.cc (the serving mesh and its facts).
//
// Thread-safety: one builder is used by one thread, once.

#ifndef LOCATOR_CORE_GIVEN_MESH_BUILDER_H_
#define LOCATOR_CORE_GIVEN_MESH_BUILDER_H_

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "locator/dataset.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/core/cgal/cdt_with_info.h"
#include "server/core/mesh/mesh_file.h"

namespace locator {

class GivenMeshBuilder {
 public:
  explicit GivenMeshBuilder(const Dataset& dataset) : d_(dataset) {}

  // Checks the mesh (see given_mesh.h) and triangulates its boundary.
  Status Check();
  // The serving mesh and its facts. Precondition: Check() succeeded.
  StatusOr<BuiltMesh> Serve();

 private:
  static constexpr uint32_t kNone = 0xffffffffu;
  // Which side of the mesh's boundary a face of cdt_ is on.
  enum class Side : uint8_t { kUnknown, kInside, kOutside };
  struct VertexInfo {
    uint32_t id = kNone;  // kNone: a vertex CGAL made where edges cross
  };
  struct FaceInfo {
    Side side = Side::kUnknown;
    uint32_t index = kNone;  // in the serving mesh, for outside faces
  };
  using Kernel = CdtKernel;
  using Cdt = CdtWithInfo<VertexInfo, FaceInfo, CGAL::Exact_predicates_tag>;
  using Face_handle = Cdt::Face_handle;

  // Edge i of a triangle is opposite corner i: it runs from corner i + 1
  // to corner i + 2, the triangle on its left. Half-edge 3 k + i.
  uint32_t From(uint32_t h) const { return tri_[h / 3][(h % 3 + 1) % 3]; }
  uint32_t To(uint32_t h) const { return tri_[h / 3][(h % 3 + 2) % 3]; }
  static uint64_t Key(uint32_t from, uint32_t to) {
    return (uint64_t{from} << 32) | to;
  }

  Status MergePoints();
  Status CheckTriangles();
  Status PairEdges();
  Status TriangulateBoundary();
  Status SideFaces();
  Status CheckUnusedPoints();
  // "mesh triangle K (a b c)", as Triangulation::Build names it.
  std::string TriangleName(size_t k) const;
  // "mesh edge (lo hi) of triangle K", as Triangulation::Build names it.
  std::string EdgeName(uint32_t h) const;
  Status Overlaps(size_t k) const;

  const Dataset& d_;
  // first_[i]: the id of point i, the index of its first occurrence.
  std::vector<uint32_t> first_;
  size_t distinct_ = 0;
  // The given triangles, counter-clockwise, by ids.
  std::vector<std::array<uint32_t, 3>> tri_;
  // twin_[h]: the half-edge of the other triangle of h's edge, or kNone
  // on the boundary.
  std::vector<uint32_t> twin_;
  size_t mesh_edges_ = 0;
  // The boundary half-edges, by Key(From, To).
  std::unordered_map<uint64_t, uint32_t> boundary_;
  Cdt cdt_;
  std::vector<Cdt::Vertex_handle> vertex_;  // by id
};

}  // namespace locator

#endif  // LOCATOR_CORE_GIVEN_MESH_BUILDER_H_
