// Triangulation: the thin adapter that owns a CGAL constrained Delaunay
// triangulation and every CGAL typedef the engine uses. Nothing outside
// server/core sees CGAL.
//
// Owns: one CGAL type for every kind of dataset, a
// Constrained_triangulation_plus_2 over a Constrained_Delaunay_triangulation_2
// (exact predicates, inexact constructions, Exact_predicates_tag: the tag that
// lets constraints cross with this kernel). Without constraints it is the
// Delaunay triangulation of the points, with the same ids as before. Vertex
// info holds the stable id and the value z. The last build step derives the
// serving mesh (serving_mesh.h), on which every locate runs; face info holds
// the finite face's index k in that mesh: k itself for an in-domain face
// (its stable triangle id 0..T-1, in the mesh's Hilbert order, so the same
// input always yields the same ids), -2 - k for a face outside the domain,
// and -1 for infinite faces. An index maps ids to vertices.
//
// Vertex ids: input point i has id i (repeats merged into the first). A
// constraint point that is not an input point gets the next id after the
// input ids, in constraint order. Where two constraints cross, CGAL inserts a
// vertex at the rounded intersection; it gets the next id after those, and
// (with values) the value interpolated along the first constraint through it,
// by distance between that constraint's endpoints.
//
// The domain (see DatasetConstraints): with rings, a face is in when the
// number of ring edges crossed from the outside is odd (breaklines never
// count); with .poly segments, the faces reachable from outside the hull or
// from a hole point without crossing a segment are out; with mesh triangles,
// exactly the given triangles are in. Without any of them every finite face
// is in.
//
// Invariants after Build(): at least one in-domain triangle exists; no
// triangle crosses a constrained edge; mesh() is the same triangulation.
//
// Thread-safety: immutable after Build(); every const method may be called
// from any number of threads.

#ifndef LOCATOR_CORE_TRIANGULATION_H_
#define LOCATOR_CORE_TRIANGULATION_H_

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/core/mesh/serving_mesh.h"

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
  using FaceBase = CGAL::Constrained_triangulation_face_base_2<
      Kernel, CGAL::Triangulation_face_base_with_info_2<int64_t, Kernel>>;
  using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
  using Cdt = CGAL::Constrained_triangulation_plus_2<
      CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds,
                                                 CGAL::Exact_predicates_tag>>;
  using Face_handle = Cdt::Face_handle;
  using Vertex_handle = Cdt::Vertex_handle;

  // Triangulates `dataset` with its constraints and marks its domain.
  // InvalidArgument if it has fewer than 3 distinct points or all of them
  // are collinear, or its constraints are bad: boundaries that cross, a hole
  // point outside the domain, a mesh that is not served as given (the error
  // names the triangle or edge), an empty domain.
  static StatusOr<std::unique_ptr<Triangulation>> Build(const Dataset& dataset);

  Triangulation(const Triangulation&) = delete;
  Triangulation& operator=(const Triangulation&) = delete;

  const Cdt& cgal() const { return dt_; }
  size_t input_points() const { return input_points_; }
  size_t num_vertices() const { return dt_.number_of_vertices(); }
  // In-domain triangles (ids 0..num_triangles()-1).
  size_t num_triangles() const { return num_triangles_; }
  // Finite faces, in the domain or not.
  size_t num_faces() const { return dt_.number_of_faces(); }
  size_t duplicates_merged() const { return duplicates_merged_; }
  // Whether some finite face is outside the domain's definition (rings,
  // segments or mesh triangles were given).
  bool has_domain() const { return has_domain_; }
  // Constraint segments inserted (breaklines, rings, segments, mesh edges).
  size_t num_constraints() const { return constraint_kinds_.size(); }
  // Connected regions of out-of-domain faces that do not touch the hull.
  size_t num_holes() const { return num_holes_; }
  // Whether the finite face f is in the domain.
  bool InDomain(Face_handle f) const { return f->info() >= 0; }
  // The index of the finite face f in mesh().
  uint32_t MeshFace(Face_handle f) const {
    return static_cast<uint32_t>(f->info() >= 0 ? f->info() : -2 - f->info());
  }
  // The index in mesh() of f's corner i, and so of its edge i: the mesh
  // rotates each face so that its corner 0 has the smallest id.
  int MeshIndex(Face_handle f, int i) const;
  // The serving mesh derived from this triangulation; it may outlive it.
  const ServingMesh& mesh() const { return *mesh_; }
  std::shared_ptr<const ServingMesh> shared_mesh() const { return mesh_; }
  // Whether the finite edge (f, i) lies along a breakline or a .poly
  // segment; false for an edge only rings or mesh triangles constrain.
  bool AlongBreakline(Face_handle f, int i) const;
  bool has_values() const { return has_values_; }
  // Bounding box of the input points.
  const BoundingBox& bounding_box() const { return box_; }
  // Bytes held by the CGAL containers and the adapter's index (not the
  // serving mesh).
  size_t MemoryBytes() const;

  bool IsInfinite(Face_handle f) const { return dt_.is_infinite(f); }
  // The vertex with id `i` (0 <= i < input_points() is input point i).
  Vertex_handle VertexOfInput(size_t i) const { return by_input_[i]; }
  // Coordinates of the vertex with stable id `id`; false if no such vertex.
  bool VertexPoint(int64_t id, Point2* p) const;
  // A finite face incident to `v`.
  Face_handle FiniteFaceAt(Vertex_handle v) const;
  // Where CGAL's locate() starts without a hint: a finite hull face.
  Face_handle DefaultStart() const;
  // XXH3 (Xxh3Digest) over every distinct vertex's (id, x, y) in id order, then
  // (for constrained datasets) the constrained edges and in-domain triangles by
  // sorted ids: equal for triangulations of the same points and domain,
  // whatever file they came from.
  uint64_t VertexDigest() const;
  // The stable ids of f's corners, counter-clockwise.
  std::array<uint32_t, 3> CornerIds(Face_handle f) const;
  // The finite face whose corners are `ids` in counter-clockwise order
  // (starting at any corner); false if there is none, e.g. an id is out of
  // range or was merged into an earlier point.
  bool FaceWithCorners(const std::array<uint32_t, 3>& ids,
                       Face_handle* face) const;

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
  // What a constraint segment is, for the domain marking.
  enum class ConstraintKind : uint8_t { kBreakline, kRing, kSegment, kMesh };
  class Builder;

  Triangulation() = default;
  Cdt dt_;
  // by_input_[id] is the vertex with that id: input point i became
  // by_input_[i] (its first occurrence's vertex); constraint points and
  // crossings follow.
  std::vector<Vertex_handle> by_input_;
  size_t input_points_ = 0;
  size_t duplicates_merged_ = 0;
  size_t num_triangles_ = 0;
  size_t num_holes_ = 0;
  bool has_domain_ = false;
  // The kind of every constraint segment CGAL knows, by its id.
  std::map<Cdt::Constraint_id, ConstraintKind> constraint_kinds_;
  BoundingBox box_;
  bool has_values_ = false;
  std::shared_ptr<const ServingMesh> mesh_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TRIANGULATION_H_
