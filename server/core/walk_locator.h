// Strategy "walk": every query walks from one fixed hull face, which is
// where CGAL's locate() starts without a hint. The baseline: O(sqrt n) faces.
//
// Thread-safety: stateless; Locate() from any thread.

#ifndef LOCATOR_CORE_WALK_LOCATOR_H_
#define LOCATOR_CORE_WALK_LOCATOR_H_

#include "server/core/point_locator.h"
#include "server/core/triangulation.h"

namespace locator {

class WalkLocator : public PointLocator {
 public:
  // `t` must outlive the locator.
  explicit WalkLocator(const Triangulation& t);

  void Locate(const Point2& q, LocateResult* result) const override;
  std::string_view name() const override { return "walk"; }
  TuningSummary Summary() const override;

 private:
  const Triangulation& t_;
  const Triangulation::Face_handle start_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_WALK_LOCATOR_H_
