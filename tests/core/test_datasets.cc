#include "tests/core/test_datasets.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>

#include "common/random.h"
#include "server/core/locator_factory.h"

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

std::unique_ptr<Triangulation> BuildTriangulation(const Dataset& dataset) {
  std::unique_ptr<Triangulation> t;
  const Status s = Triangulation::Build(dataset, &t);
  if (!s.ok()) {
    ADD_FAILURE() << "Triangulation::Build(" << dataset.source
                  << "): " << s.ToString();
    return nullptr;
  }
  return t;
}

std::unique_ptr<PointLocator> MakeLocator(std::string_view name,
                                          const Triangulation& t,
                                          const TuningOptions& options) {
  std::unique_ptr<PointLocator> locator;
  const Status s = MakePointLocator(name, t.mesh(), options, &locator);
  if (!s.ok()) {
    ADD_FAILURE() << "MakePointLocator(" << name << "): " << s.ToString();
    return nullptr;
  }
  return locator;
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
