// Triangulation::Builder: builds one Triangulation from a Dataset in steps
// (points, constraints, crossings, domain, triangle ids; see triangulation.h
// for the rules). Internal to server/core's triangulation files:
// triangulation_build.cc (points, polylines, crossings),
// triangulation_mesh.cc (a mesh given as triangles) and
// triangulation_domain.cc (domain marking and triangle ids).
//
// Thread-safety: one Builder is used by one thread, once.

#ifndef LOCATOR_CORE_TRIANGULATION_BUILDER_H_
#define LOCATOR_CORE_TRIANGULATION_BUILDER_H_

#include <string>
#include <vector>

#include "locator/dataset.h"
#include "locator/geometry.h"
#include "locator/status.h"
#include "server/core/cgal/triangulation.h"

namespace locator {

// Builds one Triangulation. Face info is used as scratch while marking:
// -1 unvisited, else the nesting depth, then 1 (in) or 0 (out), then the
// triangle id or -1, and finally the mesh index (see triangulation.h).
class Triangulation::Builder {
 public:
  Builder(const Dataset& dataset, Triangulation* t)
      : dataset_(dataset), t_(*t), dt_(t->dt_) {}

  Status Run() {
    Status s = InsertPoints();
    if (s.ok()) s = InsertConstraints();
    if (s.ok()) s = NameCrossings();
    if (s.ok()) s = MarkDomain();
    if (s.ok()) s = NumberTriangles();
    if (s.ok()) s = BuildServingMesh();
    return s;
  }

 private:
  using Edge = Cdt::Edge;
  // A constraint segment as the input named it, for messages.
  struct InputSegment {
    Cdt::Constraint_id id;
    ConstraintKind kind;
    std::string name;
  };

  Status InsertPoints();
  Status InsertConstraints();
  Status InsertPolylines(const std::vector<Polyline>& lines, bool closed,
                         ConstraintKind kind, const std::string& what);
  Status InsertMeshEdges();
  // "mesh triangle K (a b c)", for messages.
  std::string MeshTriangleName(size_t k) const;
  // The vertex for p (a new one gets the next id and `value`).
  Vertex_handle VertexAt(const Point2& p, double value);
  void AddSegment(Vertex_handle a, Vertex_handle b, ConstraintKind kind,
                  std::string name);
  Status NameCrossings();
  Status MarkDomain();
  Status MarkMesh();
  void MarkRingDepth();
  Status EatSegmentRegions();
  // Sets info 0 on every face reachable from `seed` without crossing a
  // segment or ring edge.
  void Eat(Face_handle seed);
  Status NumberTriangles();
  // Derives the serving mesh and sets the final face info (triangulation.h).
  Status BuildServingMesh();
  // The number of regions of out-of-domain faces that do not reach the hull.
  size_t CountHoles();
  // The number of ring segments along edge (f, i); barrier: any boundary.
  int RingCount(Face_handle f, int i) const;
  bool IsBarrier(Face_handle f, int i) const;

  bool IsBoundary(ConstraintKind kind) const {
    return kind == ConstraintKind::kRing || kind == ConstraintKind::kSegment ||
           kind == ConstraintKind::kMesh;
  }

  const Dataset& dataset_;
  Triangulation& t_;
  Cdt& dt_;
  const DatasetConstraints& c_ = dataset_.constraints;
  std::vector<InputSegment> segments_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TRIANGULATION_BUILDER_H_
