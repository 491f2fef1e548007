#include "tests/core/test_datasets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "common/random.h"
#include "server/core/strategies/locator_factory.h"

namespace locator::test {

Dataset GridDataset(int k) {
  Dataset ds;
  for (int y = 0; y < k; ++y) {
    for (int x = 0; x < k; ++x) ds.points.push_back({double(x), double(y)});
  }
  ds.source = "grid";
  return ds;
}

double Plane(const Point2& p) { return 2 * p.x + 3 * p.y + 1; }

Dataset PlaneDataset(size_t n, uint64_t seed) {
  Dataset ds = GenerateUniform(n, seed);
  for (const Point2& p : ds.points) ds.values.push_back(Plane(p));
  return ds;
}

Dataset DenseClusterDataset(size_t sparse, size_t dense, double side,
                            uint64_t seed) {
  Dataset ds = GenerateUniform(sparse, seed);
  std::mt19937_64 rng(seed + 1);
  for (size_t i = 0; i < dense; ++i) {
    const double x = UniformDouble(rng, 0.5, 0.5 + side);
    const double y = UniformDouble(rng, 0.5, 0.5 + side);
    ds.points.push_back({x, y});
  }
  ds.source = "dense-cluster";
  return ds;
}

Dataset PointsDataset(std::vector<Point2> points) {
  Dataset ds;
  ds.points = std::move(points);
  ds.source = "points";
  return ds;
}

Dataset CocircularDataset() {
  constexpr int64_t kRadius = 5525;
  Dataset ds;
  for (int64_t s = 1; s <= 3; ++s) {
    const int64_t r = s * kRadius;
    for (int64_t x = -r; x <= r; ++x) {
      const int64_t y2 = r * r - x * x;
      const auto y = static_cast<int64_t>(std::llround(std::sqrt(double(y2))));
      for (const int64_t candidate : {y - 1, y, y + 1}) {
        if (candidate < 0 || candidate * candidate != y2) continue;
        ds.points.push_back({double(x), double(candidate)});
        if (candidate > 0) ds.points.push_back({double(x), double(-candidate)});
      }
    }
  }
  for (const Point2& p :
       {Point2{0, 0}, Point2{100, 7}, Point2{-4000, 3000}, Point2{9000, -1}}) {
    ds.points.push_back(p);
  }
  ds.source = "cocircular";
  return ds;
}

Dataset LinesDataset(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Dataset ds;
  const size_t per_line = std::max<size_t>(n / 8, 2);
  for (size_t i = 0; i < per_line; ++i) {
    const double t = double(i) / double(per_line - 1);
    for (const double slope : {0.25, 0.5, 1.0, 2.0}) {
      ds.points.push_back({t, slope * t / 2});  // a fan from the origin
    }
    ds.points.push_back({t, 0.9});      // a horizontal line
    ds.points.push_back({t, 1.0});      // the top of the hull
    ds.points.push_back({0, t});        // the left side of the hull
    ds.points.push_back({1, 0.5 * t});  // part of the right side
  }
  for (int i = 0; i < 5; ++i) {
    ds.points.push_back(
        {UniformDouble(rng, 0.1, 0.9), UniformDouble(rng, 0.1, 0.8)});
  }
  ds.source = "lines";
  return ds;
}

Dataset WithRepeats(Dataset dataset, int copies, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const size_t n = dataset.points.size();
  for (int c = 0; c < copies; ++c) {
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    for (const size_t i : order) {
      dataset.points.push_back(dataset.points[i]);
      if (dataset.has_values()) dataset.values.push_back(dataset.values[i]);
    }
  }
  dataset.source += "+repeats";
  return dataset;
}

std::vector<std::array<uint32_t, 3>> TriangleSet(const ServingMesh& mesh) {
  std::vector<std::array<uint32_t, 3>> triangles(mesh.num_faces());
  for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
    triangles[f] = mesh.CornerIds(f);
    std::sort(triangles[f].begin(), triangles[f].end());
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

std::unique_ptr<Triangulation> BuildTriangulation(const Dataset& dataset) {
  StatusOr<std::unique_ptr<Triangulation>> t = Triangulation::Build(dataset);
  if (!t.ok()) {
    ADD_FAILURE() << "Triangulation::Build(" << dataset.source
                  << "): " << t.status().ToString();
    return nullptr;
  }
  return *std::move(t);
}

std::unique_ptr<PointLocator> MakeLocator(std::string_view name,
                                          const Triangulation& t,
                                          const TuningOptions& options) {
  StatusOr<std::unique_ptr<PointLocator>> locator =
      MakePointLocator(name, t.mesh(), options);
  if (!locator.ok()) {
    ADD_FAILURE() << "MakePointLocator(" << name
                  << "): " << locator.status().ToString();
    return nullptr;
  }
  return *std::move(locator);
}

std::vector<Point2> UniformQueries(const BoundingBox& box, size_t n,
                                   uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Point2> queries(n);
  for (Point2& q : queries) {
    q.x = UniformDouble(rng, box.min_x, box.max_x);
    q.y = UniformDouble(rng, box.min_y, box.max_y);
  }
  return queries;
}

BoundingBox MapUnitSquare(const BoundingBox& box, double x0, double y0,
                          double side) {
  return BoundingBox{box.min_x + x0 * box.width(),
                     box.min_y + y0 * box.height(),
                     box.min_x + (x0 + side) * box.width(),
                     box.min_y + (y0 + side) * box.height()};
}

bool Covers(const BoundingBox& outer, const BoundingBox& inner) {
  const double sx = 1e-12 * inner.width(), sy = 1e-12 * inner.height();
  return outer.min_x <= inner.min_x + sx && outer.min_y <= inner.min_y + sy &&
         outer.max_x >= inner.max_x - sx && outer.max_y >= inner.max_y - sy;
}

bool SomeRegionCovers(const std::vector<BoundingBox>& regions,
                      const BoundingBox& inner) {
  for (const BoundingBox& r : regions) {
    if (Covers(r, inner)) return true;
  }
  return false;
}

std::vector<Point2> ConstrainedEdgePoints(const Triangulation& t) {
  std::vector<Point2> points;
  const auto& dt = t.cgal();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    if (!dt.is_constrained(*e)) continue;
    const Point2 a =
        Triangulation::FromCgal(e->first->vertex(dt.cw(e->second))->point());
    const Point2 b =
        Triangulation::FromCgal(e->first->vertex(dt.ccw(e->second))->point());
    points.push_back(a);
    points.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
  }
  return points;
}

std::vector<LocateResult> ReferenceAnswers(const Triangulation& t,
                                           std::span<const Point2> queries) {
  std::vector<LocateResult> refs;
  refs.reserve(queries.size());
  for (const Point2& q : queries) refs.push_back(t.ReferenceLocate(q));
  return refs;
}

double MeanCost(const PointLocator& locator, std::span<const Point2> queries) {
  if (queries.empty()) return 0;
  double sum = 0;
  LocateResult r;
  for (const Point2& q : queries) {
    locator.Locate(q, &r);
    sum += r.cost.total();
  }
  return sum / static_cast<double>(queries.size());
}

}  // namespace locator::test
