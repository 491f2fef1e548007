// Barycentric against exact rationals: every point's coordinates within
// 2^-40, in plump triangles (double), needles (long double) and triangles
// at the ends of the double range (exact), for points inside, on and
// around the triangle. TriangleBarycentric, fed the walk's orientation
// filters, equals Barycentric bit for bit.

#include "server/core/geometry/barycentric.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace locator {
namespace {

// The oracle: signed areas from CGAL's exact-constructions kernel.
std::array<double, 3> ExactCoordinates(const Point2& a, const Point2& b,
                                       const Point2& c, const Point2& q) {
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  const K::Point_2 pa(a.x, a.y), pb(b.x, b.y), pc(c.x, c.y), pq(q.x, q.y);
  const K::FT whole = CGAL::area(pa, pb, pc);
  const K::FT to_a = CGAL::area(pq, pb, pc) / whole;
  const K::FT to_b = CGAL::area(pa, pq, pc) / whole;
  const K::FT to_c = CGAL::area(pa, pb, pq) / whole;
  // exact(): a lazy number's to_double is its interval's, not the exact
  // value rounded.
  return {CGAL::to_double(CGAL::exact(to_a)),
          CGAL::to_double(CGAL::exact(to_b)),
          CGAL::to_double(CGAL::exact(to_c))};
}

struct TriangleCase {
  const char* name;
  Point2 a, b, c;
};

class BarycentricTest : public ::testing::TestWithParam<TriangleCase> {};

TEST_P(BarycentricTest, EveryPointWithin2ToThe40) {
  const TriangleCase& t = GetParam();
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> weight(-0.5, 1.5);
  for (int i = 0; i < 2000; ++i) {
    // q at random barycentric weights (inside and around the triangle),
    // rounded to doubles; the corners themselves first.
    const double u = i < 3 ? (i == 0) : weight(random);
    const double v = i < 3 ? (i == 1) : weight(random);
    const Point2 q{t.a.x * u + t.b.x * v + t.c.x * (1 - u - v),
                   t.a.y * u + t.b.y * v + t.c.y * (1 - u - v)};
    if (!IsFinite(q)) continue;
    const std::array<double, 3> got = Barycentric(t.a, t.b, t.c, q);
    const std::array<double, 3> want = ExactCoordinates(t.a, t.b, t.c, q);
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(got[k], want[k], 0x1p-40)
          << t.name << ": point " << i << ", coordinate " << k;
    }
  }
}

// Bit for bit: a scan's value is then the one a locate gives.
TEST_P(BarycentricTest, FromTheFiltersEqualsBarycentric) {
  const TriangleCase& t = GetParam();
  const TriangleBarycentric triangle(t.a, t.b, t.c);
  std::mt19937_64 random(6);
  std::uniform_real_distribution<double> weight(-0.5, 1.5);
  for (int i = 0; i < 2000; ++i) {
    const double u = weight(random);
    const double v = weight(random);
    const Point2 q{t.a.x * u + t.b.x * v + t.c.x * (1 - u - v),
                   t.a.y * u + t.b.y * v + t.c.y * (1 - u - v)};
    if (!IsFinite(q)) continue;
    const std::array<double, 3> got = triangle.Of(
        q, OrientationFilter(t.b, t.c, q), OrientationFilter(t.c, t.a, q));
    const std::array<double, 3> want = Barycentric(t.a, t.b, t.c, q);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(std::bit_cast<uint64_t>(got[k]),
                std::bit_cast<uint64_t>(want[k]))
          << t.name << ": point " << i << ", coordinate " << k << ": " << got[k]
          << " against " << want[k];
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    DoubleLongDoubleAndExact, BarycentricTest,
    ::testing::Values(
        TriangleCase{"plump", {0, 0}, {1, 0}, {0.3, 0.9}},
        TriangleCase{"utm",
                     {500012.5, 5500031.25},
                     {500022.5, 5500030},
                     {500015, 5500041}},
        // Too thin for double's error bound: long double resolves it.
        TriangleCase{"needle", {0, 0}, {1, 1}, {2, 2.0004}},
        // Products below 2^-960: out of double's range.
        TriangleCase{"tiny", {0, 0}, {1e-160, 0}, {0, 1e-160}},
        // Spanning 1e-300..1e150: long double's area may not resolve.
        TriangleCase{
            "extreme needle", {1e-300, 0}, {1e150, 1e-300}, {2e150, 3e-300}}),
    [](const ::testing::TestParamInfo<TriangleCase>& info) {
      std::string name = info.param.name;
      for (char& ch : name) {
        if (ch == ' ') ch = '_';
      }
      return name;
    });

}  // namespace
}  // namespace locator
