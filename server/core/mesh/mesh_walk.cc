#include "server/core/mesh/mesh_walk.h"

namespace locator {

namespace {

// The faces Walk() takes by the filter alone before the exact walk takes
// over: a locate's start, a scan's last point or a start table's last
// sub-cell centre is most often a few faces from q.
constexpr int kMaxClearSteps = 16;

// The serving mesh as a VisibilityWalk topology.
class MeshTopology {
 public:
  using Face = uint32_t;

  explicit MeshTopology(const ServingMesh& mesh) : mesh_(mesh) {}

  Side SideOf(Face f, int i, const Point2& q) const {
    return Orientation(mesh_.CornerPoint(f, Ccw(i)),
                       mesh_.CornerPoint(f, Cw(i)), q);
  }
  bool Next(Face f, int i, Face* next) const {
    *next = mesh_.Neighbor(f, i);
    return !ServingMesh::IsHull(*next);
  }
  int EntryIndex(Face next, Face from) const {
    return mesh_.MirrorIndex(next, from);
  }
  // The neighbours' records load while f's corners are compared: a step
  // then waits for one load (the new corner), not two.
  void Prefetch(Face f) const {
    for (int i = 0; i < 3; ++i) {
      const uint32_t n = mesh_.Neighbor(f, i);
      if (!ServingMesh::IsHull(n)) mesh_.PrefetchFace(n);
    }
  }

 private:
  const ServingMesh& mesh_;
};

}  // namespace

MeshWalkOutcome Walk(const ServingMesh& mesh, uint32_t start, const Point2& q) {
  MeshWalkOutcome clear{.face = start};
  if (ClearWalk(mesh, q, kMaxClearSteps, &clear)) return clear;
  MeshWalkOutcome w = VisibilityWalk(MeshTopology(mesh), clear.face, q);
  // The face the filter stopped at counts once.
  w.faces_visited += clear.faces_visited - 1;
  return w;
}

uint32_t ClosedDomainFace(const ServingMesh& mesh, const MeshWalkOutcome& at) {
  if (at.type == LocationType::kOutsideConvexHull) return ServingMesh::kNoFace;
  uint32_t f = at.face;
  int feature = at.feature;
  if (mesh.InDomain(f) || mesh.MoveIntoDomain(&f, at.type, &feature)) return f;
  return ServingMesh::kNoFace;
}

uint32_t WalkAndDescribe(const ServingMesh& mesh, uint32_t start,
                         const Point2& q, LocateResult* result, Detail detail) {
  MeshWalkOutcome w = Walk(mesh, start, q);
  if (w.type == LocationType::kOutsideConvexHull) {
    mesh.NearestVisibleHullEdge(&w.face, &w.feature, q);
  }
  mesh.Describe(w.face, w.type, w.feature, q, result, detail);
  result->cost.faces_visited = w.faces_visited;
  return w.face;
}

}  // namespace locator
