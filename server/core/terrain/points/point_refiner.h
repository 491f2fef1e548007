// PointRefiner: greedy insertion (Garland and Heckbert) of scattered points
// into a TinMesh whose triangles tagged 1 are the domain. Each such
// triangle keeps the points it holds in a bucket (a linked list through
// the points) and its worst one; a queue orders the triangles by that
// error; the worst point of the worst triangle becomes a vertex, and the
// points of the triangles the insertion rewrote are put in their new
// triangles' buckets.
//
// Two measures of a triangle's error at a point:
//   kFace    Barycentric in the triangle, whatever the point's location:
//            what the build refines with;
//   kServed  what the engine answers: EdgeBarycentric for a point on an
//            edge (exact orientation), Barycentric inside: the
//            certificate.
// A point's error is that of every repeat of it (the same coordinates):
// the engine serves one value there.
//
// Thread-safety: none; one thread refines one mesh.

#ifndef LOCATOR_CORE_TERRAIN_POINT_REFINER_H_
#define LOCATOR_CORE_TERRAIN_POINT_REFINER_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/terrain/tin_mesh.h"
#include "server/core/terrain/tin_progress.h"
#include "server/core/terrain/triangle_queue.h"

namespace locator {

enum class PointMeasure { kFace, kServed };

class PointRefiner {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;

  // Refines `mesh` (any doubles; vertex v's value is (*vertex_values)[v])
  // with the input `points` and their `values`, all of which must outlive
  // this, until every point is within `target` of the surface.
  PointRefiner(std::span<const Point2> points, std::span<const double> values,
               TinMesh* mesh, std::vector<double>* vertex_values,
               double target);

  // Puts point i, which lies in the closed in-domain triangle t and is no
  // vertex, in t's bucket.
  void Add(uint32_t i, uint32_t t);
  // Point i has repeats whose values (its own included) span [lo, hi].
  void SetRepeats(uint32_t i, double lo, double hi);
  // Input points at vertex v (v's own point, repeats, or points on a
  // vertex of the first mesh) have values spanning [lo, hi]: an error the
  // mesh cannot change.
  void AddAtVertex(uint32_t v, double lo, double hi);

  // Measures every in-domain triangle; queues those beyond the target.
  void ScanAll(PointMeasure measure);
  // Inserts the worst point while one lies beyond the target and the mesh
  // has fewer than max_vertices vertices (0: no limit), reporting to
  // `progress` every few hundred insertions. Internal if a point is lost
  // (a bug).
  Status Refine(uint64_t max_vertices, TinProgressReporter* progress);
  // The largest error of any point now.
  double MaxError() const;
  // The input point each vertex inserted since construction was, in order
  // (vertex first_inserted() + k is inserted()[k]).
  const std::vector<uint32_t>& inserted() const { return inserted_; }
  uint32_t first_inserted() const { return first_inserted_; }

 private:
  // Point i's error against the value `v` the surface has there.
  double PointError(uint32_t i, double v) const;
  // The surface's value at point i in triangle t, by `measure_`.
  double SurfaceAt(uint32_t t, uint32_t i) const;
  // Measures triangle t (worst point and error) and (de)queues it.
  void Rescan(uint32_t t);
  // Moves the points of the touched triangles into their new buckets.
  Status Rebucket(uint32_t inserted_point);

  const std::span<const Point2> points_;
  const std::span<const double> values_;
  TinMesh* const mesh_;
  std::vector<double>* const vertex_values_;
  const double target_;
  const uint32_t first_inserted_;
  PointMeasure measure_ = PointMeasure::kFace;
  // Buckets: head_[t] is t's first point, next_[i] the point after i.
  LargeVector<uint32_t> head_;
  std::vector<uint32_t> next_;
  // Each triangle's worst point (kNone if none) and its error.
  LargeVector<uint32_t> candidate_;
  LargeVector<double> error_;
  TriangleQueue queue_;
  std::unordered_map<uint32_t, std::pair<double, double>> repeats_;
  double vertex_error_ = 0;
  std::vector<uint32_t> inserted_;
  std::vector<uint32_t> pool_;  // Rebucket's scratch
};

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_POINT_REFINER_H_
