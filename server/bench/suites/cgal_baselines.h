// CgalBaselines: CGAL's own point-location methods over the same points, as
// the yardstick for locator-bench: locate() without a hint, locate() hinted
// with the previous answer, and the Delaunay hierarchy
// (Triangulation_hierarchy_2; 2D has no Fast_location policy).
//
// Owns a Triangulation_hierarchy_2 built from the dataset (the plain
// triangulation is borrowed). Answers are converted to LocateResult with
// vertex ids, so Triangulation::Agrees() can check them.
//
// Thread-safety: not thread-safe (the last-answer hint is state).

#ifndef LOCATOR_BENCH_CGAL_BASELINES_H_
#define LOCATOR_BENCH_CGAL_BASELINES_H_

#include <cstddef>
#include <memory>

#include "locator/dataset_sources.h"
#include "locator/locate_result.h"
#include "server/core/cgal/triangulation.h"

namespace locator {

class CgalBaselines {
 public:
  // `t` must outlive this object and be built from `dataset`.
  CgalBaselines(const Triangulation& t, const Dataset& dataset);
  ~CgalBaselines();

  // CGAL locate() on t, no hint.
  LocateResult LocateNoHint(const Point2& q) const;
  // CGAL locate() on t, hinted with the face of the previous call.
  LocateResult LocateLastHint(const Point2& q);
  // Triangulation_hierarchy_2::locate().
  LocateResult LocateHierarchy(const Point2& q) const;

  // Bytes of the hierarchy (all levels), and seconds it took to build.
  size_t hierarchy_bytes() const;
  double hierarchy_build_seconds() const { return hierarchy_seconds_; }

 private:
  struct Hierarchy;

  const Triangulation& t_;
  Triangulation::Face_handle last_;
  std::unique_ptr<Hierarchy> hierarchy_;
  double hierarchy_seconds_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_BENCH_CGAL_BASELINES_H_
