#include "server/core/strategies/jump_and_walk_locator.h"

#include <cmath>

#include "server/core/geometry/fast_random.h"
#include "server/core/mesh/mesh_walk.h"

namespace locator {

namespace {

uint32_t CubeRootCeil(size_t n) {
  auto m = static_cast<uint32_t>(std::cbrt(static_cast<double>(n)));
  while (uint64_t{m} * m * m < n) ++m;  // exact, whatever cbrt rounded to
  return m < 1 ? 1 : m;
}

}  // namespace

JumpAndWalkLocator::JumpAndWalkLocator(const ServingMesh& mesh)
    : mesh_(mesh), m_(CubeRootCeil(mesh.num_vertices())) {}

void JumpAndWalkLocator::Locate(const Point2& q, LocateResult* result,
                                Detail detail) const {
  const size_t n = mesh_.num_faces();
  auto best = static_cast<uint32_t>(ThreadRandom() % n);
  double best_d2 = SquaredDistance(mesh_.CornerPoint(best, 0), q);
  for (uint32_t k = 1; k < m_; ++k) {
    const auto f = static_cast<uint32_t>(ThreadRandom() % n);
    const double d2 = SquaredDistance(mesh_.CornerPoint(f, 0), q);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = f;
    }
  }
  result->cost = LocateCost();
  WalkAndDescribe(mesh_, best, q, result, detail);
  result->cost.comparisons = m_;
}

}  // namespace locator
