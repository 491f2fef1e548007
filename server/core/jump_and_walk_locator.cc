#include "server/core/jump_and_walk_locator.h"

#include <cmath>

#include "server/core/fast_random.h"
#include "server/core/walk.h"

namespace locator {

namespace {

uint32_t CubeRootCeil(size_t n) {
  auto m = static_cast<uint32_t>(std::cbrt(static_cast<double>(n)));
  while (uint64_t{m} * m * m < n) ++m;  // exact, whatever cbrt rounded to
  return m < 1 ? 1 : m;
}

}  // namespace

JumpAndWalkLocator::JumpAndWalkLocator(const Triangulation& t)
    : t_(t), m_(CubeRootCeil(t.num_vertices())) {}

void JumpAndWalkLocator::Locate(const Point2& q, LocateResult* result) const {
  const size_t n = t_.input_points();
  Triangulation::Vertex_handle best = t_.VertexOfInput(ThreadRandom() % n);
  double best_d2 = SquaredDistance(Triangulation::FromCgal(best->point()), q);
  for (uint32_t k = 1; k < m_; ++k) {
    const auto v = t_.VertexOfInput(ThreadRandom() % n);
    const double d2 = SquaredDistance(Triangulation::FromCgal(v->point()), q);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = v;
    }
  }
  result->cost = LocateCost();
  WalkAndDescribe(t_, t_.FiniteFaceAt(best), q, result);
  result->cost.comparisons = m_;
}

}  // namespace locator
