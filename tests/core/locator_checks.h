// Checks that a locator's answers are right: they agree with
// Triangulation::ReferenceLocate (via Triangulation::Agrees) and are
// self-consistent (ids, corners, barycentrics and the location type match the
// triangle, checked with CGAL's exact orientation predicate, independently of
// CGAL's locate()).

#ifndef LOCATOR_TESTS_CORE_LOCATOR_CHECKS_H_
#define LOCATOR_TESTS_CORE_LOCATOR_CHECKS_H_

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/strategies/point_locator.h"

namespace locator::test {

// Barycentric coordinates of answers inside the hull sum to 1 within this.
constexpr double kBarycentricTolerance = 1e-9;

// The vertex ids of every triangle, by stable triangle id, counter-clockwise
// from the smallest (as the serving mesh orders corners).
class TriangleIndex {
 public:
  explicit TriangleIndex(const Triangulation& t);

  size_t size() const { return ids_.size(); }
  const std::array<int64_t, 3>& ids(int64_t triangle_id) const {
    return ids_[static_cast<size_t>(triangle_id)];
  }

 private:
  std::vector<std::array<int64_t, 3>> ids_;
};

// "(x, y) FACE tri 12 ids [3 4 5] ..." for failure messages.
std::string DescribeAnswer(const Point2& q, const LocateResult& r);

// Whether `got` is a well-formed answer for q on `t` (see file comment),
// whatever the reference says.
::testing::AssertionResult AnswerIsConsistent(const Triangulation& t,
                                              const TriangleIndex& index,
                                              const Point2& q,
                                              const LocateResult& got);

// Locates every query with `locator` and checks each answer agrees with
// `refs` (parallel to `queries`) and is consistent. Reports the first few
// failures and the number of failures.
::testing::AssertionResult AllAgree(const PointLocator& locator,
                                    const Triangulation& t,
                                    const TriangleIndex& index,
                                    std::span<const Point2> queries,
                                    std::span<const LocateResult> refs);

// As above, computing the references and the index itself.
void ExpectAllAgree(const PointLocator& locator, const Triangulation& t,
                    std::span<const Point2> queries);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_CORE_LOCATOR_CHECKS_H_
