#include "server/bench/suites/cgal_baselines.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <chrono>
#include <numeric>
#include <utility>
#include <vector>

namespace locator {

namespace {

using Kernel = Triangulation::Kernel;
using HVertexBase = CGAL::Triangulation_hierarchy_vertex_base_2<
    CGAL::Triangulation_vertex_base_with_info_2<int64_t, Kernel>>;
using HTds = CGAL::Triangulation_data_structure_2<
    HVertexBase, CGAL::Triangulation_face_base_2<Kernel>>;
using HDelaunay = CGAL::Delaunay_triangulation_2<Kernel, HTds>;
using HTriangulation = CGAL::Triangulation_hierarchy_2<HDelaunay>;

// Converts any CGAL answer (face, type, index) whose vertices carry input ids
// to a LocateResult with ids, the hull edge for points outside.
template <class Dt, class Id>
LocateResult Convert(const Dt& dt, typename Dt::Face_handle f,
                     typename Dt::Locate_type lt, int li, Id id) {
  LocateResult r;
  auto fill = [&](typename Dt::Face_handle g) {
    for (int i = 0; i < 3; ++i) {
      r.vertex_ids[i] = dt.is_infinite(g->vertex(i)) ? -1 : id(g->vertex(i));
    }
  };
  switch (lt) {
    case Dt::FACE:
      r.type = LocationType::kFace;
      fill(f);
      break;
    case Dt::EDGE:
      r.type = LocationType::kEdge;
      fill(f);
      r.feature_index = static_cast<int8_t>(li);
      break;
    case Dt::VERTEX:
      r.type = LocationType::kVertex;
      fill(f);
      r.feature_index = static_cast<int8_t>(li);
      break;
    default: {
      r.type = LocationType::kOutsideConvexHull;
      const int k = f->index(dt.infinite_vertex());
      r.hull_edge_ids = {id(f->vertex(Dt::cw(k))), id(f->vertex(Dt::ccw(k)))};
      fill(f);
      break;
    }
  }
  return r;
}

}  // namespace

struct CgalBaselines::Hierarchy {
  HTriangulation ht;
};

CgalBaselines::CgalBaselines(const Triangulation& t, const Dataset& dataset)
    : t_(t), last_(t.DefaultStart()), hierarchy_(new Hierarchy) {
  const auto start = std::chrono::steady_clock::now();
  // The hierarchy's range insert takes no vertex info, so do what it does
  // (spatial sort, then hinted inserts) and set the ids on the way.
  std::vector<Kernel::Point_2> points;
  points.reserve(dataset.points.size());
  for (const Point2& p : dataset.points)
    points.push_back(Triangulation::ToCgal(p));
  std::vector<size_t> order(points.size());
  std::iota(order.begin(), order.end(), size_t{0});
  using SortTraits = CGAL::Spatial_sort_traits_adapter_2<
      Kernel, CGAL::Pointer_property_map<Kernel::Point_2>::type>;
  CGAL::spatial_sort(order.begin(), order.end(),
                     SortTraits(CGAL::make_property_map(points)));
  HTriangulation::Face_handle hint;
  for (size_t i : order) {
    const auto v = hierarchy_->ht.insert(points[i], hint);
    // Merged duplicates keep the first occurrence's id, as in Triangulation.
    v->info() = t.VertexOfInput(i)->info().id;
    hint = v->face();
  }
  hierarchy_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
}

CgalBaselines::~CgalBaselines() = default;

LocateResult CgalBaselines::LocateNoHint(const Point2& q) const {
  return t_.ReferenceLocate(q);
}

LocateResult CgalBaselines::LocateLastHint(const Point2& q) {
  const auto& dt = t_.cgal();
  Triangulation::Cdt::Locate_type lt;
  int li = -1;
  const auto f = dt.locate(Triangulation::ToCgal(q), lt, li, last_);
  // Keep the hint finite: CGAL may answer with an infinite face.
  if (!dt.is_infinite(f)) last_ = f;
  return Convert(dt, f, lt, li, [](auto v) { return v->info().id; });
}

LocateResult CgalBaselines::LocateHierarchy(const Point2& q) const {
  const HTriangulation& ht = hierarchy_->ht;
  HTriangulation::Locate_type lt;
  int li = -1;
  const auto f = ht.locate(Triangulation::ToCgal(q), lt, li);
  return Convert(ht, f, lt, li, [](auto v) { return v->info(); });
}

size_t CgalBaselines::hierarchy_bytes() const {
  // Triangulation_hierarchy_2 keeps its levels private; level 0 is the
  // hierarchy object itself and each upper level holds ~1/30 of the
  // vertices of the one below (CGAL's ratio), so the upper levels add
  // about 1/29 of level 0.
  const auto& tds = hierarchy_->ht.tds();
  const size_t level0 = tds.vertices().capacity() * sizeof(HTds::Vertex) +
                        tds.faces().capacity() * sizeof(HTds::Face);
  return level0 + level0 / 29;
}

}  // namespace locator
