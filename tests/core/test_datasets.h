// Shared fixtures for the core tests: dataset builders, query streams and
// the triangulation / locator factories the tests build on.
//
// Factories that can fail record a non-fatal gtest failure and return
// nullptr, so callers write `ASSERT_NE(t, nullptr)`.

#ifndef LOCATOR_TESTS_CORE_TEST_DATASETS_H_
#define LOCATOR_TESTS_CORE_TEST_DATASETS_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "common/workload.h"
#include "locator/dataset_sources.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/tuning_options.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/point_locator.h"

namespace locator::test {

// The k x k integer grid {0..k-1}^2, row by row (id = y * k + x). Every
// square of four points is co-circular, so the Delaunay triangulation is
// not unique: a stress test for exact predicates.
Dataset GridDataset(int k);

// The plane every PlaneDataset value lies on: z = 2x + 3y + 1.
double Plane(const Point2& p);
// `n` uniform points in the unit square with value Plane(p).
Dataset PlaneDataset(size_t n, uint64_t seed);

// `sparse` uniform points in the unit square plus `dense` uniform points in
// the tiny square [0.5, 0.5 + side]^2.
Dataset DenseClusterDataset(size_t sparse, size_t dense, double side,
                            uint64_t seed);

// A dataset from raw points (no values).
Dataset PointsDataset(std::vector<Point2> points);

// The integer points of the circles x^2 + y^2 = (s * 5525)^2 for s = 1, 2,
// 3 (180 points each: 5525 = 5^2 * 13 * 17 has many), their centre and a
// few points between: large sets of exactly co-circular points.
Dataset CocircularDataset();

// `n` points on a few lines (a fan through the origin, two parallels, the
// axes, with repeats of the lines' own spacing) plus a handful off them:
// collinear runs everywhere, on the hull too.
Dataset LinesDataset(size_t n, uint64_t seed);

// `dataset` with every point repeated `copies` times more (values too),
// the repeats shuffled in after their first occurrence.
Dataset WithRepeats(Dataset dataset, int copies, uint64_t seed);

// The triangles of `mesh` as sorted triples of public vertex ids, sorted.
std::vector<std::array<uint32_t, 3>> TriangleSet(const ServingMesh& mesh);

// Triangulates `dataset`; nullptr (and a test failure) if that fails.
std::unique_ptr<Triangulation> BuildTriangulation(const Dataset& dataset);

// Builds strategy `name` over `t`; nullptr (and a test failure) on error.
std::unique_ptr<PointLocator> MakeLocator(
    std::string_view name, const Triangulation& t,
    const TuningOptions& options = TuningOptions());

// `n` points uniform in `box`.
std::vector<Point2> UniformQueries(const BoundingBox& box, size_t n,
                                   uint64_t seed);

// The square [x0, x0 + side] x [y0, y0 + side] of the unit square, mapped
// into `box` the way Workload maps its queries.
BoundingBox MapUnitSquare(const BoundingBox& box, double x0, double y0,
                          double side);

// The 1-cluster workload's square, mapped into `box`.
inline BoundingBox OneClusterSquare(const BoundingBox& box) {
  return MapUnitSquare(box, 0.48, 0.48, 0.04);
}

// Whether `outer` contains all of `inner`, up to rounding: a region built
// from grid cells may miss a square on the same lines by an ulp.
bool Covers(const BoundingBox& outer, const BoundingBox& inner);
// Whether one of `regions` Covers() `inner`.
bool SomeRegionCovers(const std::vector<BoundingBox>& regions,
                      const BoundingBox& inner);

// For every constrained edge of `t` (breaklines, boundaries; every edge of
// a mesh given as triangles), one of its ends and its midpoint: queries on
// vertices and, where the midpoint is representable, exactly on the edge.
std::vector<Point2> ConstrainedEdgePoints(const Triangulation& t);

// Triangulation::ReferenceLocate for every query.
std::vector<LocateResult> ReferenceAnswers(const Triangulation& t,
                                           std::span<const Point2> queries);

// Mean LocateResult::cost.total() of `locator` over `queries`.
double MeanCost(const PointLocator& locator, std::span<const Point2> queries);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_CORE_TEST_DATASETS_H_
