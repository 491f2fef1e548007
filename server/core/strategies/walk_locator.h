// Strategy "walk": every query walks from one fixed hull face, which is
// where CGAL's locate() starts without a hint. The baseline: O(sqrt n) faces.
//
// Thread-safety: stateless; Locate() from any thread.

#ifndef LOCATOR_CORE_WALK_LOCATOR_H_
#define LOCATOR_CORE_WALK_LOCATOR_H_

#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/point_locator.h"

namespace locator {

class WalkLocator : public PointLocator {
 public:
  // `mesh` must outlive the locator.
  explicit WalkLocator(const ServingMesh& mesh);

  void Locate(const Point2& q, LocateResult* result,
              Detail detail = Detail::kFull) const override;
  std::string_view name() const override { return "walk"; }
  TuningSummary Summary() const override;

 private:
  const ServingMesh& mesh_;
  const uint32_t start_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_WALK_LOCATOR_H_
