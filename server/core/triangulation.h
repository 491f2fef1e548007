// Triangulation: the thin adapter that owns a CGAL Delaunay triangulation and
// every CGAL typedef the engine uses. Nothing outside server/core sees CGAL.
//
// Owns: the CGAL Delaunay_triangulation_2 (exact predicates, inexact
// constructions), vertex info (the stable input id and the value z), face
// info (a stable triangle id 0..F-1 assigned after the build, in CGAL's
// finite-face iteration order, so the same input always yields the same ids),
// and an index from input position to vertex for O(1) random sampling.
//
// Invariants after Build(): at least one finite triangle exists (>= 3
// distinct, not all collinear points); repeated input points are merged into
// the first occurrence, whose id the vertex keeps.
//
// Thread-safety: immutable after Build(); every const method may be called
// from any number of threads.

#ifndef LOCATOR_CORE_TRIANGULATION_H_
#define LOCATOR_CORE_TRIANGULATION_H_

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "common/geometry.h"
#include "common/status.h"
#include "server/core/dataset.h"
#include "server/core/locate_result.h"

namespace locator {

class Triangulation {
 public:
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using CgalPoint = Kernel::Point_2;
  struct VertexInfo {
    int64_t id = -1;
    double value = 0;
  };
  using VertexBase =
      CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
  using FaceBase = CGAL::Triangulation_face_base_with_info_2<int64_t, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
  using Face_handle = Delaunay::Face_handle;
  using Vertex_handle = Delaunay::Vertex_handle;

  // Triangulates `dataset`. InvalidArgument if it has fewer than 3 distinct
  // points or all of them are collinear.
  static Status Build(const Dataset& dataset,
                      std::unique_ptr<Triangulation>* out);

  Triangulation(const Triangulation&) = delete;
  Triangulation& operator=(const Triangulation&) = delete;

  const Delaunay& cgal() const { return dt_; }
  size_t input_points() const { return by_input_.size(); }
  size_t num_vertices() const { return dt_.number_of_vertices(); }
  size_t num_triangles() const { return dt_.number_of_faces(); }
  size_t duplicates_merged() const { return input_points() - num_vertices(); }
  bool has_values() const { return has_values_; }
  // Bounding box of the input points.
  const BoundingBox& bounding_box() const { return box_; }
  // Bytes held by the CGAL containers and the adapter's index.
  size_t MemoryBytes() const;
  // Finite edges, as endpoint pairs: all of them if there are at most
  // `max_edges`, else every k-th of CGAL's edge order (k as small as keeps
  // the count within `max_edges`). Deterministic; O(edges).
  std::vector<std::array<Point2, 2>> SampleEdges(size_t max_edges) const;

  bool IsInfinite(Face_handle f) const { return dt_.is_infinite(f); }
  // The vertex that input point `i` (0 <= i < input_points()) became.
  Vertex_handle VertexOfInput(size_t i) const { return by_input_[i]; }
  // Coordinates of the vertex with stable id `id`; false if no such vertex.
  bool VertexPoint(int64_t id, Point2* p) const;
  // A finite face incident to `v`.
  Face_handle FiniteFaceAt(Vertex_handle v) const;
  // Where CGAL's locate() starts without a hint: a finite hull face.
  Face_handle DefaultStart() const;
  // Fnv1a64 over every distinct vertex's (id, x, y) in id order: equal for
  // triangulations of the same points, whatever file they came from.
  uint64_t VertexDigest() const;
  // The stable ids of f's corners, counter-clockwise.
  std::array<uint32_t, 3> CornerIds(Face_handle f) const;
  // The finite face whose corners are `ids` in counter-clockwise order
  // (starting at any corner); false if there is none, e.g. an id is out of
  // range or was merged into an earlier point.
  bool FaceWithCorners(const std::array<uint32_t, 3>& ids,
                       Face_handle* face) const;

  // Fills `out` (all but cost) for q located at `type` in the finite face f.
  // `feature` is the edge index for kEdge and kOutsideConvexHull (the hull
  // edge of f that q is beyond), the vertex index for kVertex, else unused.
  void Describe(Face_handle f, LocationType type, int feature, const Point2& q,
                LocateResult* out) const;

  static CgalPoint ToCgal(const Point2& p) { return CgalPoint(p.x, p.y); }
  static Point2 FromCgal(const CgalPoint& p) { return Point2{p.x(), p.y()}; }

  // CGAL's own locate() (no hint), converted: the reference every strategy
  // must agree with. Cost fields are zero.
  LocateResult ReferenceLocate(const Point2& q) const;
  // Whether `got` names the same location as `reference` for q: same type;
  // the same triangle (same three vertex ids) for kFace; a triangle containing
  // the same edge or vertex for kEdge/kVertex; a hull edge that sees q (q
  // strictly on its outer side) for kOutsideConvexHull. Uses ids only, so
  // answers that came over the wire can be checked too.
  bool Agrees(const Point2& q, const LocateResult& got,
              const LocateResult& reference) const;

 private:
  Triangulation() = default;

  Delaunay dt_;
  // by_input_[i] is the vertex input point i became; a vertex's stable id
  // is the input position of its first occurrence.
  std::vector<Vertex_handle> by_input_;
  BoundingBox box_;
  bool has_values_ = false;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TRIANGULATION_H_
