// Orientation() against CGAL's exact predicate where a double filter is
// most likely to be wrong: exactly and nearly collinear triples, at every
// scale from subnormal to near overflow, and triples mixing scales.

#include "server/core/cgal/orientation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace locator {
namespace {

Side Exact(const Point2& a, const Point2& b, const Point2& c) {
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  return static_cast<Side>(static_cast<int>(
      CGAL::orientation(P(a.x, a.y), P(b.x, b.y), P(c.x, c.y))));
}

// Orientation(a, b, c) equals CGAL's, and the filter alone claims a side
// only where CGAL says so.
void ExpectAgrees(const Point2& a, const Point2& b, const Point2& c) {
  const Side exact = Exact(a, b, c);
  EXPECT_EQ(Orientation(a, b, c), exact);
  const OrientationFilter filter(a, b, c);
  if (filter.ClearlyLeft()) EXPECT_EQ(exact, Side::kLeft);
  if (filter.ClearlyRight()) EXPECT_EQ(exact, Side::kRight);
}

bool ClearlyLeft(const Point2& a, const Point2& b, const Point2& c) {
  return OrientationFilter(a, b, c).ClearlyLeft();
}

// Collinear triples by construction: small integer steps along a line,
// times a power of two, so that every coordinate is exact.
class OrientationTest : public ::testing::TestWithParam<int> {};

TEST_P(OrientationTest, AgreesWithCgalOnAndNextToLines) {
  const double scale = std::ldexp(1.0, GetParam());
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coordinate(-1000, 1000);
  std::uniform_int_distribution<int> multiple(-3, 3);
  std::uniform_int_distribution<int> nudge(1, 3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 100000; ++i) {
    const int x = coordinate(rng), y = coordinate(rng);
    const int dx = coordinate(rng), dy = coordinate(rng);
    const int m = multiple(rng);
    const Point2 a{scale * x, scale * y};
    const Point2 b{scale * (x + dx), scale * (y + dy)};
    const Point2 c{scale * (x + m * dx), scale * (y + m * dy)};
    ASSERT_NO_FATAL_FAILURE(ExpectAgrees(a, b, c)) << "triple " << i;
    if (dx != 0 || dy != 0) {
      ASSERT_EQ(Orientation(a, b, c), Side::kOn) << "triple " << i;
    }
    // A few ulps off the line: a determinant far below the terms' rounding.
    Point2 off = c;
    for (int k = nudge(rng); k > 0; --k) off.x = std::nextafter(off.x, 1e308);
    ExpectAgrees(a, b, off);
    // A point of the line a-b rounded to doubles, for arbitrary a and b:
    // its determinant is about as large as the error of computing it.
    const Point2 p{scale * unit(rng), scale * unit(rng)};
    const Point2 q{scale * unit(rng), scale * unit(rng)};
    const double t = unit(rng) * 3;
    const Point2 r{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
    ExpectAgrees(p, q, r);
    if (HasFailure()) FAIL() << "triple " << i;
  }
}

// Powers of two: 1, 2^-500, 2^500, 2^-1000 (products underflow), 2^990
// (differences overflow), 2^-1070 (subnormal coordinates).
INSTANTIATE_TEST_SUITE_P(Scales, OrientationTest,
                         ::testing::Values(0, -500, 500, -1000, 990, -1070));

TEST(OrientationMixedScalesTest, AgreesWithCgal) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-320, 300);
  for (int i = 0; i < 200000; ++i) {
    Point2 p[3];
    for (Point2& q : p) {
      q = {unit(rng) * std::pow(10.0, exponent(rng)),
           unit(rng) * std::pow(10.0, exponent(rng))};
    }
    ExpectAgrees(p[0], p[1], p[2]);
    if (HasFailure()) FAIL() << "triple " << i;
  }
}

TEST(OrientationFilterTest, DecidesPlumpTriplesAndNeverDegenerateOnes) {
  EXPECT_TRUE(ClearlyLeft({0, 0}, {1, 0}, {0, 1}));
  EXPECT_TRUE(ClearlyLeft({1e-100, 0}, {2e-100, 0}, {1e-100, 1e-100}));
  EXPECT_FALSE(ClearlyLeft({0, 0}, {0, 1}, {1, 0}));  // right
  EXPECT_TRUE(OrientationFilter({0, 0}, {0, 1}, {1, 0}).ClearlyRight());
  EXPECT_FALSE(ClearlyLeft({0, 0}, {1, 1}, {3, 3}));  // on the line
  // Products out of the filter's range: the exact predicate must decide.
  EXPECT_FALSE(ClearlyLeft({0, 0}, {0x1p-1074, 0}, {0, 0x1p-1074}));
  EXPECT_FALSE(ClearlyLeft({0, 0}, {1e300, 0}, {0, 1e300}));
}

}  // namespace
}  // namespace locator
