// Strategy "jump-and-walk" (Mücke, Saias & Zhu): per query, sample
// m = ceil(n^(1/3)) points at random, and walk from the one closest to the
// query. No preprocessing; expected O(n^(1/3)) cost on uniform data. The
// samples are the first corners of m random triangles: the mesh keeps no
// vertex-to-triangle index, and triangles are spread like the points (about
// two per point), so the samples are too.
//
// Thread-safety: stateless apart from thread-local random bits.

#ifndef LOCATOR_CORE_JUMP_AND_WALK_LOCATOR_H_
#define LOCATOR_CORE_JUMP_AND_WALK_LOCATOR_H_

#include <cstdint>

#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/point_locator.h"

namespace locator {

class JumpAndWalkLocator : public PointLocator {
 public:
  // `mesh` must outlive the locator.
  explicit JumpAndWalkLocator(const ServingMesh& mesh);

  void Locate(const Point2& q, LocateResult* result,
              Detail detail = Detail::kFull) const override;
  std::string_view name() const override { return "jump-and-walk"; }
  TuningSummary Summary() const override { return TuningSummary(); }

  // Number of points sampled per query.
  uint32_t sample_size() const { return m_; }

 private:
  const ServingMesh& mesh_;
  const uint32_t m_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_JUMP_AND_WALK_LOCATOR_H_
