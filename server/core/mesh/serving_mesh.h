// ServingMesh: the immutable, flat triangulation every locate runs on.
//
// CGAL (Triangulation) builds the triangulation and stays the reference in
// tests; the serving mesh is derived from it once and holds only what a query
// touches, in plain arrays with 32-bit indices:
//
//   triangles  F records of 24 bytes: corner[3], neighbor[3]. Corners are
//              counter-clockwise, corner 0 the one with the smallest
//              public id. Edge i is opposite corner i and runs from
//              corner Ccw(i) to corner Cw(i), the triangle on its left.
//              The top bit of corner[i] is set when edge i is a constrained
//              edge (breakline, boundary, .poly segment or mesh edge).
//              neighbor[i] is the triangle across edge i, or for a hull edge
//              kHullBit | its position in hull().
//   points     V vertex coordinates; values V doubles (empty without values);
//              ids V public vertex ids (the stable ids of Triangulation).
//   hull       the hull edges as Edge(face, i) codes, in a ring where each
//              edge ends where the one before it starts, from the edge
//              ending at the hull vertex with the smallest public id.
//
// Order: triangles are numbered in-domain first, so that a triangle's index
// is its public triangle id (0..num_triangles()-1, stable: the same input
// always gives the same ids); the finite faces outside the domain follow
// (num_triangles()..num_faces()-1). Within each group, and for vertices,
// the order is the Hilbert curve over the bounding box (of centroids for
// triangles; ties by the corners' public ids; for vertices, by id), so that
// neighbours are near in memory. So the mesh of a triangulation does not
// depend on how it was built (CGAL in Triangulation, or tiles).
//
// The arrays are views: a mesh owns them through an opaque storage (vectors
// after a build), so a mesh can also be served from a mapped file.
//
// Thread-safety: immutable; every method may be called from any thread.

#ifndef LOCATOR_CORE_SERVING_MESH_H_
#define LOCATOR_CORE_SERVING_MESH_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "server/core/mesh/prefetch.h"

namespace locator {

// Index of corner i + 1 / i + 2 of a triangle (0..2), as CGAL's ccw()/cw().
inline int Ccw(int i) { return i == 2 ? 0 : i + 1; }
inline int Cw(int i) { return i == 0 ? 2 : i - 1; }

struct MeshTriangle {
  std::array<uint32_t, 3> corner;
  std::array<uint32_t, 3> neighbor;
};
static_assert(sizeof(MeshTriangle) == 24);

class ServingMesh {
 public:
  static constexpr uint32_t kHullBit = 0x80000000u;
  static constexpr uint32_t kConstrainedBit = 0x80000000u;
  static constexpr uint32_t kIndexMask = 0x7fffffffu;
  // The most vertices or triangles a mesh may have (31-bit indices).
  static constexpr size_t kMaxElements = kIndexMask;

  // Owns the arrays the views point into.
  class Storage {
   public:
    virtual ~Storage() = default;
  };
  // The arrays of a mesh built in memory.
  class VectorStorage : public Storage {
   public:
    std::vector<MeshTriangle> triangles;
    std::vector<Point2> points;
    std::vector<double> values;
    std::vector<uint32_t> ids;
    std::vector<uint32_t> hull;
  };

  struct Arrays {
    std::span<const MeshTriangle> triangles;
    std::span<const Point2> points;
    std::span<const double> values;
    std::span<const uint32_t> ids;
    std::span<const uint32_t> hull;
    uint32_t in_domain = 0;  // triangles [0, in_domain) are in the domain
    BoundingBox box;         // of the input points
    uint64_t input_points = 0;
    uint64_t digest = 0;  // Triangulation::VertexDigest()
  };

  // A mesh over `arrays`, which `storage` keeps alive. Precondition: the
  // arrays are a valid mesh (as ServingMeshBuilder makes, or as a checked
  // file maps).
  ServingMesh(std::unique_ptr<const Storage> storage, const Arrays& arrays);

  ServingMesh(const ServingMesh&) = delete;
  ServingMesh& operator=(const ServingMesh&) = delete;

  // An edge as one code: 3 * face + i.
  static uint32_t Edge(uint32_t face, int i) { return 3 * face + i; }
  static uint32_t EdgeFace(uint32_t edge) { return edge / 3; }
  static int EdgeIndex(uint32_t edge) { return static_cast<int>(edge % 3); }

  size_t num_vertices() const { return a_.points.size(); }
  // Finite faces, in the domain or not.
  size_t num_faces() const { return a_.triangles.size(); }
  // In-domain triangles: faces 0..num_triangles()-1.
  size_t num_triangles() const { return a_.in_domain; }
  bool has_values() const { return !a_.values.empty(); }
  const BoundingBox& bounding_box() const { return a_.box; }
  uint64_t input_points() const { return a_.input_points; }
  // One past the largest public vertex id, and at least input_points():
  // constraint points that are not input points take the ids after them.
  // The first call scans the ids (not the constructor: a mapped mesh larger
  // than RAM serves without reading them).
  uint64_t id_bound() const;
  // Equal for meshes of the same points and domain (VertexDigest()).
  uint64_t digest() const { return a_.digest; }
  const Arrays& arrays() const { return a_; }
  std::span<const uint32_t> hull() const { return a_.hull; }

  bool InDomain(uint32_t f) const { return f < a_.in_domain; }
  // Mesh vertex index of corner i of f.
  uint32_t Corner(uint32_t f, int i) const {
    return a_.triangles[f].corner[i] & kIndexMask;
  }
  const Point2& CornerPoint(uint32_t f, int i) const {
    return a_.points[Corner(f, i)];
  }
  // The raw neighbour field of edge i of f (see IsHull()).
  uint32_t Neighbor(uint32_t f, int i) const {
    return a_.triangles[f].neighbor[i];
  }
  static bool IsHull(uint32_t neighbor) { return neighbor & kHullBit; }
  // A hint that face f's record is about to be read.
  void PrefetchFace(uint32_t f) const { Prefetch(&a_.triangles[f]); }
  // A hint that f's corners are about to be read; reads f's record.
  void PrefetchCorners(uint32_t f) const {
    for (int i = 0; i < 3; ++i) Prefetch(&CornerPoint(f, i));
  }
  bool IsConstrained(uint32_t f, int i) const {
    return a_.triangles[f].corner[i] & kConstrainedBit;
  }
  // The index of the edge of n that is shared with f (n = Neighbor(f, i)).
  int MirrorIndex(uint32_t n, uint32_t f) const {
    const auto& nb = a_.triangles[n].neighbor;
    return nb[0] == f ? 0 : nb[1] == f ? 1 : 2;
  }
  // The corner of f that is mesh vertex v, or -1.
  int IndexOf(uint32_t f, uint32_t v) const {
    for (int i = 0; i < 3; ++i) {
      if (Corner(f, i) == v) return i;
    }
    return -1;
  }
  int64_t PublicId(uint32_t v) const { return a_.ids[v]; }
  // Public ids of f's corners, counter-clockwise.
  std::array<uint32_t, 3> CornerIds(uint32_t f) const;
  // A hull face: where a walk starts without a hint.
  uint32_t DefaultStart() const { return EdgeFace(a_.hull[0]); }
  // The in-domain triangle whose centroid follows q's position along the
  // Hilbert curve (the last one if none does): a start near q found by
  // binary search over the triangle order, O(log F), without a table.
  uint32_t TriangleNear(const Point2& q) const;
  // The Hilbert key over `box` of the centroid of triangle a, b, c: the
  // order of the triangles within each group.
  static uint32_t CentroidKey(const Point2& a, const Point2& b, const Point2& c,
                              const BoundingBox& box);

  // Fills `out` (all but cost) for q located at `type` in face f, as
  // Triangulation::Describe does: for kOutsideConvexHull, `feature` is the
  // hull edge of f nearest q; a face outside the domain answers
  // kOutsideDomain with the nearest boundary edge unless q is on an edge or
  // vertex it shares with an in-domain triangle.
  // With Detail::kLocation it leaves barycentric and value out.
  void Describe(uint32_t f, LocationType type, int feature, const Point2& q,
                LocateResult* out, Detail detail = Detail::kFull) const;
  // The sum of b[i] times the value of corner i of f: the linear value at
  // barycentrics b. Finite, between the corners' values, even for values
  // near +-DBL_MAX. Precondition: has_values().
  double CornerValue(uint32_t f, const std::array<double, 3>& b) const;
  // For a point on edge/vertex `feature` (kEdge/kVertex) of the
  // out-of-domain face f, an in-domain face sharing it (updating f and
  // feature); false if none.
  bool MoveIntoDomain(uint32_t* f, LocationType type, int* feature) const;
  // Among the hull edges that see q (a chain containing `*edge` of `*face`,
  // a hull edge that sees q), the nearest one; ties go to the smaller
  // public ids, so the answer does not depend on where the walk left.
  void NearestVisibleHullEdge(uint32_t* face, int* edge, const Point2& q) const;

  // For each triple of public ids, the face whose corners they are,
  // counter-clockwise from any corner, or kNoFace. O(V + F) plus the
  // degrees of the first corners.
  static constexpr uint32_t kNoFace = 0xffffffffu;
  std::vector<uint32_t> FacesWithCorners(
      std::span<const std::array<uint32_t, 3>> ids) const;

  // Calls visit(g) for the faces g around vertex v of face f, other than f:
  // round one way, then, if the hull stopped that, the other way. Stops at
  // the first g for which visit returns true, and returns whether there
  // was one.
  template <class Visit>
  bool AnyFaceAround(uint32_t f, uint32_t v, Visit visit) const {
    for (const bool forward : {true, false}) {
      uint32_t g = f;
      for (;;) {
        const int j = IndexOf(g, v);
        const uint32_t n = Neighbor(g, forward ? Ccw(j) : Cw(j));
        if (IsHull(n)) break;
        if (n == f) return false;  // round v, which is not on the hull
        if (visit(n)) return true;
        g = n;
      }
    }
    return false;
  }

  // Edges, as endpoint pairs: all of them if there are at most `max_edges`,
  // else every k-th in mesh order (each edge once, from its lower-numbered
  // face; k as small as keeps the count within `max_edges`). O(F).
  std::vector<std::array<Point2, 2>> SampleEdges(size_t max_edges) const;

  // Bytes of the arrays (what a mesh file holds).
  size_t MemoryBytes() const;

 private:
  void DescribeOutsideDomain(uint32_t f, const Point2& q,
                             LocateResult* out) const;

  std::unique_ptr<const Storage> storage_;
  Arrays a_;
  mutable std::once_flag id_bound_once_;
  mutable uint64_t id_bound_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CORE_SERVING_MESH_H_
