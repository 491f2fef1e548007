// ScanFace: where a scan of points, each near the last, is in the serving
// mesh, so that most points are placed without a walk.
//
// Thread-safety: not thread-safe; one per scan, on the scanning thread.
// Invariant: when loaded, face() is an in-domain face and the corners held
// are its own.

#ifndef LOCATOR_CORE_MESH_SCAN_FACE_H_
#define LOCATOR_CORE_MESH_SCAN_FACE_H_

#include <cstdint>
#include <optional>

#include "locator/geometry.h"
#include "server/core/geometry/barycentric.h"
#include "server/core/mesh/mesh_walk.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// The in-domain face a scan is in, its corners loaded once for all the
// points it holds; a point beyond it is followed across the faces it is
// clearly beyond, as ClearWalk steps. A scan's next point most often lies
// in its last point's face or a few faces on: it is then placed with no
// walk, and valued from the cross products that placed it.
class ScanFace {
 public:
  // The faces Holds() steps by the filters alone before the exact walk
  // takes over: a raster's next cell is a few faces from its last at most
  // zoom levels of a terrain's tiles.
  static constexpr int kMaxSteps = 16;

  explicit ScanFace(const ServingMesh& mesh) : mesh_(mesh) {}

  // Loads the face a walk answered if that is kFace in the domain; forgets
  // the face otherwise.
  void Load(const MeshWalkOutcome& w) {
    loaded_ = w.type == LocationType::kFace && mesh_.InDomain(w.face);
    if (loaded_) LoadFace(w.face);
  }

  // Forgets the loaded face (a new row starts elsewhere).
  void Forget() { loaded_ = false; }

  // True when a face holds q clearly inside, as Walk() would answer (kFace
  // there): the loaded one, or one reached from it in at most kMaxSteps
  // steps, each across an edge that q is clearly beyond into an in-domain
  // face (then loaded). False when none is loaded, a step would leave the
  // hull or the domain, a test is undecided, or the steps run out; then
  // face() is a good start for the exact walk.
  bool Holds(const Point2& q) {
    if (!loaded_) return false;
    for (int step = 0;; ++step) {
      filters_ = FaceFilters(corner_[0], corner_[1], corner_[2], q);
      if (filters_.ClearlyInside()) return true;
      if (step == kMaxSteps) return false;
      const int exit = filters_.ClearExit();
      if (exit < 0) return false;
      const uint32_t next = mesh_.Neighbor(face_, exit);
      if (ServingMesh::IsHull(next) || !mesh_.InDomain(next)) return false;
      LoadFace(next);
    }
  }

  // Walks to q, which Holds() refused, from the last face the filters
  // reached (`from` when no face is loaded), and loads the face the walk
  // answered.
  MeshWalkOutcome WalkTo(const Point2& q, uint32_t from) {
    const MeshWalkOutcome w = Walk(mesh_, loaded_ ? face_ : from, q);
    Load(w);
    return w;
  }

  uint32_t face() const { return face_; }
  // The linear value at q, which Holds() placed here: ValueAt()'s, bit
  // for bit. Precondition: the mesh has values.
  double LinearValue(const Point2& q) {
    if (!barycentric_) barycentric_.emplace(corner_[0], corner_[1], corner_[2]);
    return mesh_.CornerValue(
        face_, barycentric_->Of(q, filters_.edge[0], filters_.edge[1]));
  }

 private:
  void LoadFace(uint32_t f) {
    face_ = f;
    for (int i = 0; i < 3; ++i) corner_[i] = mesh_.CornerPoint(f, i);
    barycentric_.reset();  // made for the face's first value
  }

  const ServingMesh& mesh_;
  bool loaded_ = false;
  uint32_t face_ = 0;
  std::array<Point2, 3> corner_;
  std::optional<TriangleBarycentric> barycentric_;
  // The filters of the point Holds() last tested.
  FaceFilters filters_{{}, {}, {}, {}};
};

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_SCAN_FACE_H_
