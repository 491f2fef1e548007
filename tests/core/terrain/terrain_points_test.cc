// SimplifyPoints: the certificate checked by brute force at every input
// point on the served TIN; kept points exact; constraint vertices kept;
// the domain's holes; repeats; budgets; bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "locator/dataset.h"
#include "locator/engine.h"
#include "server/core/terrain/points/simplify_points.h"
#include "tests/core/locator_checks.h"
#include "tests/core/terrain/terrain_test_support.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using test::WithError;

double Hills(const Point2& p) {
  return 40 * std::sin(p.x * 7) * std::cos(p.y * 5) + 15 * std::sin(p.x * 23) +
         10 * p.y;
}

// `n` uniform points of the unit square with Hills() values and noise.
Dataset HillPoints(size_t n, uint64_t seed) {
  Dataset d = GenerateUniform(n, seed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0, 0.5);
  for (const Point2& p : d.points) d.values.push_back(Hills(p) + noise(rng));
  return d;
}

SimplificationStats Simplify(const Dataset& in, const TinOptions& options,
                             Dataset* tin) {
  SimplificationStats stats;
  const Status s = SimplifyPoints(in, options, tin, &stats);
  EXPECT_TRUE(s.ok()) << s.ToString();
  return stats;
}

TEST(SimplifyPointsTest, CertificateIsTheServedErrorAtEveryPoint) {
  const Dataset in = HillPoints(6000, 3);
  for (const double e : {10.0, 2.0, 0.5}) {
    SCOPED_TRACE(e);
    Dataset tin;
    const SimplificationStats stats = Simplify(in, WithError(e), &tin);
    const test::ServedAtPoints served = test::MeasureServedAtPoints(in, tin);
    EXPECT_NEAR(served.max_error, stats.max_error, 1e-9);
    EXPECT_LE(stats.max_error, e);
    EXPECT_LE(served.max_error, e + 1e-9);
    EXPECT_EQ(served.unserved, 0u);
    EXPECT_EQ(stats.unserved_samples, 0u);
    EXPECT_EQ(stats.source_samples, in.points.size());
    EXPECT_LT(stats.vertices, in.points.size());
    EXPECT_EQ(stats.vertices, tin.points.size());
    EXPECT_EQ(stats.triangles, tin.constraints.triangles.size());
  }
}

TEST(SimplifyPointsTest, KeptPointsAreInputPointsWithTheirValues) {
  const Dataset in = HillPoints(3000, 5);
  Dataset tin;
  Simplify(in, WithError(1), &tin);
  std::map<std::tuple<double, double>, double> input;
  for (size_t i = 0; i < in.points.size(); ++i) {
    input.emplace(std::tuple(in.points[i].x, in.points[i].y), in.values[i]);
  }
  for (size_t k = 0; k < tin.points.size(); ++k) {
    const auto it = input.find(std::tuple(tin.points[k].x, tin.points[k].y));
    ASSERT_NE(it, input.end()) << "vertex " << k << " is not an input point";
    EXPECT_EQ(tin.values[k], it->second);
  }
}

// Points on a plane but one: the plane needs only its hull; the one point
// off it by less than E is dropped, and the certificate is its offset.
TEST(SimplifyPointsTest, ErrorIsMeasuredAtDroppedPoints) {
  Dataset in = test::PlaneDataset(500, 2);
  in.points.push_back({0.5, 0.5});
  in.values.push_back(test::Plane({0.5, 0.5}) + 0.25);
  Dataset tin;
  const SimplificationStats stats = Simplify(in, WithError(0.3), &tin);
  EXPECT_LT(tin.points.size(), 20u);  // the hull's corners
  EXPECT_NEAR(stats.max_error, 0.25, 1e-9);
  // A tighter target keeps it.
  const SimplificationStats tight = Simplify(in, WithError(0.2), &tin);
  EXPECT_LE(tight.max_error, 0.2);
  EXPECT_NE(
      std::find_if(tin.points.begin(), tin.points.end(),
                   [](const Point2& p) { return p.x == 0.5 && p.y == 0.5; }),
      tin.points.end());
}

TEST(SimplifyPointsTest, ConstraintVerticesAreKeptAndHolesUnserved) {
  Dataset in = HillPoints(4000, 7);
  // A breakline through the middle and a square hole, on dataset points
  // and points of their own with values.
  Polyline breakline{{in.points[0], in.points[1], in.points[2]}, {}};
  in.constraints.breaklines.push_back(breakline);
  Polyline outer{{{-0.1, -0.1}, {1.1, -0.1}, {1.1, 1.1}, {-0.1, 1.1}},
                 {0, 0, 0, 0}};
  Polyline hole{{{0.6, 0.6}, {0.6, 0.8}, {0.8, 0.8}, {0.8, 0.6}}, {1, 2, 3, 4}};
  in.constraints.rings = {outer, hole};
  Dataset tin;
  const SimplificationStats stats = Simplify(in, WithError(3), &tin);
  for (const Polyline* line : {&breakline, &outer, &hole}) {
    for (const Point2& p : line->points) {
      EXPECT_NE(std::find_if(
                    tin.points.begin(), tin.points.end(),
                    [&](const Point2& q) { return q.x == p.x && q.y == p.y; }),
                tin.points.end())
          << p.x << " " << p.y;
    }
  }
  uint64_t in_hole = 0;
  for (const Point2& p : in.points) {
    in_hole += p.x > 0.6 && p.x < 0.8 && p.y > 0.6 && p.y < 0.8;
  }
  EXPECT_GT(in_hole, 0u);
  EXPECT_EQ(stats.unserved_samples, in_hole);
  const test::ServedAtPoints served = test::MeasureServedAtPoints(in, tin);
  EXPECT_EQ(served.unserved, in_hole);
  EXPECT_NEAR(served.max_error, stats.max_error, 1e-9);
  EXPECT_LE(stats.max_error, 3);
}

// Repeats are one vertex (the first one's value); the others count in the
// certificate at their own values.
TEST(SimplifyPointsTest, RepeatsCountAtTheirOwnValues) {
  Dataset in = test::PlaneDataset(300, 4);
  const Point2 p = in.points[10];
  in.points.push_back(p);
  in.values.push_back(in.values[10] + 0.4);
  Dataset tin;
  const SimplificationStats stats = Simplify(in, WithError(0.1), &tin);
  EXPECT_NEAR(stats.max_error, 0.4, 1e-9);
  const test::ServedAtPoints served = test::MeasureServedAtPoints(in, tin);
  EXPECT_NEAR(served.max_error, 0.4, 1e-9);
}

TEST(SimplifyPointsTest, MaxPointsIsABudget) {
  const Dataset in = HillPoints(3000, 9);
  TinOptions options = WithError(0);
  options.max_points = 200;
  Dataset tin;
  const SimplificationStats stats = Simplify(in, options, &tin);
  EXPECT_EQ(stats.vertices, 200u);
  EXPECT_GT(stats.max_error, 0);
  EXPECT_NEAR(test::MeasureServedAtPoints(in, tin).max_error, stats.max_error,
              1e-9);
  options.max_points = 3;  // below the hull's corners
  SimplificationStats refused;
  const Status s = SimplifyPoints(in, options, &tin, &refused);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("max_points is 3"), std::string::npos)
      << s.message();
}

TEST(SimplifyPointsTest, ServedTinAgreesWithCgal) {
  const Dataset in = HillPoints(5000, 11);
  Dataset tin;
  Simplify(in, WithError(1), &tin);
  std::unique_ptr<Triangulation> t = test::BuildTriangulation(tin);
  ASSERT_NE(t, nullptr);
  std::vector<Point2> queries =
      test::UniformQueries(t->bounding_box().Inflated(0.05), 3000, 2);
  queries.insert(queries.end(), in.points.begin(), in.points.begin() + 2000);
  std::unique_ptr<PointLocator> locator = test::MakeLocator("self-tuning", *t);
  ASSERT_NE(locator, nullptr);
  test::ExpectAllAgree(*locator, *t, queries);
}

TEST(SimplifyPointsTest, BadInputIsRefused) {
  const auto refused = [](const Dataset& in, const std::string& needle) {
    Dataset tin;
    SimplificationStats stats;
    const Status s = SimplifyPoints(in, WithError(1), &tin, &stats);
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << needle;
    EXPECT_NE(s.message().find(needle), std::string::npos) << s.message();
  };
  Dataset no_values = GenerateUniform(10, 1);
  refused(no_values, "needs a value at every point");
  Dataset mesh = test::PlaneDataset(10, 1);
  mesh.constraints.triangles.push_back({0, 1, 2});
  refused(mesh, "served as given");
  Dataset nan = test::PlaneDataset(10, 1);
  nan.values[3] = NAN;
  refused(nan, "the value of point 3 is not finite");
  Dataset line;
  for (int i = 0; i < 5; ++i) {
    line.points.push_back({double(i), double(i)});
    line.values.push_back(i);
  }
  refused(line, "collinear");
}

}  // namespace
}  // namespace locator
