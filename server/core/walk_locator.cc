#include "server/core/walk_locator.h"

#include "server/core/walk.h"

namespace locator {

WalkLocator::WalkLocator(const Triangulation& t)
    : t_(t), start_(t.DefaultStart()) {}

void WalkLocator::Locate(const Point2& q, LocateResult* result) const {
  result->cost = LocateCost();
  WalkAndDescribe(t_, start_, q, result);
}

TuningSummary WalkLocator::Summary() const {
  TuningSummary s;
  s.start_points.push_back(Triangulation::FromCgal(start_->vertex(0)->point()));
  s.start_point_count = 1;
  return s;
}

}  // namespace locator
