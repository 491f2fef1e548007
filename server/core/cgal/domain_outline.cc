#include "server/core/cgal/domain_outline.h"

#include <algorithm>
#include <utility>

#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {
namespace {

using Segments = std::vector<std::array<Point2, 2>>;

// Every k-th of `all` in a canonical order (each segment from its
// lexicographically smaller end; segments sorted), so that the outline does
// not depend on CGAL's edge order, which differs between builds of the same
// dataset (CGAL's insertion order is randomized); k as small as keeps at
// most `max_edges`.
Segments Thinned(Segments all, size_t max_edges) {
  const auto less = [](const Point2& a, const Point2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  for (auto& [a, b] : all) {
    if (less(b, a)) std::swap(a, b);
  }
  std::sort(all.begin(), all.end(), [&less](const auto& s, const auto& t) {
    return less(s[0], t[0]) || (!less(t[0], s[0]) && less(s[1], t[1]));
  });
  if (all.size() <= max_edges) return all;
  Segments kept;
  if (max_edges == 0) return kept;
  const size_t stride = (all.size() + max_edges - 1) / max_edges;
  kept.reserve(max_edges);
  for (size_t i = 0; i < all.size(); i += stride) kept.push_back(all[i]);
  return kept;
}

}  // namespace

DomainOutline OutlineOf(const Triangulation& t, size_t max_edges) {
  const auto& dt = t.cgal();
  // Whether the face beyond an edge is outside the domain (or the hull).
  const auto out = [&t](Triangulation::Face_handle f) {
    return t.IsInfinite(f) || !t.InDomain(f);
  };
  Segments boundary, breaklines;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Triangulation::Face_handle f = e->first;
    const int i = e->second;
    const Triangulation::Face_handle g = f->neighbor(i);
    const std::array<Point2, 2> segment = {
        Triangulation::FromCgal(f->vertex(dt.ccw(i))->point()),
        Triangulation::FromCgal(f->vertex(dt.cw(i))->point())};
    if (t.has_domain() && out(f) != out(g)) {
      boundary.push_back(segment);
    } else if (t.AlongBreakline(f, i)) {
      breaklines.push_back(segment);
    }
  }
  return DomainOutline{Thinned(std::move(boundary), max_edges),
                       Thinned(std::move(breaklines), max_edges)};
}

DomainOutline OutlineOfMesh(const ServingMesh& mesh, size_t max_edges) {
  Segments boundary;
  for (uint32_t f = 0; f < mesh.num_triangles(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t n = mesh.Neighbor(f, i);
      if (ServingMesh::IsHull(n) || !mesh.InDomain(n)) {
        boundary.push_back(
            {mesh.CornerPoint(f, Ccw(i)), mesh.CornerPoint(f, Cw(i))});
      }
    }
  }
  return DomainOutline{Thinned(std::move(boundary), max_edges), {}};
}

}  // namespace locator
