#include "server/core/strategies/walk_locator.h"

#include "server/core/mesh/mesh_walk.h"

namespace locator {

WalkLocator::WalkLocator(const ServingMesh& mesh)
    : mesh_(mesh), start_(mesh.DefaultStart()) {}

void WalkLocator::Locate(const Point2& q, LocateResult* result,
                         Detail detail) const {
  result->cost = LocateCost();
  WalkAndDescribe(mesh_, start_, q, result, detail);
}

TuningSummary WalkLocator::Summary() const {
  TuningSummary s;
  s.start_points.push_back(mesh_.CornerPoint(start_, 0));
  s.start_point_count = 1;
  return s;
}

}  // namespace locator
