#include "server/bench/datasets/quality_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "common/random.h"

namespace locator::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<
    uint32_t, Kernel, CGAL::Delaunay_mesh_vertex_base_2<Kernel>>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds,
                                               CGAL::Exact_predicates_tag>;

// The size field of quality_mesh.h: the longest edge allowed at p.
struct SizeField {
  Point2 focus;
  double scale;

  double operator()(const Point2& p) const {
    const double d = std::sqrt(SquaredDistance(p, focus));
    return scale * (0.08 + std::min(1.0, d / 0.35));
  }
};

// Delaunay_mesh_size_criteria_2 with the size bound taken from a size field
// at the triangle's centroid instead of a constant.
class GradedCriteria : public CGAL::Delaunay_mesh_size_criteria_2<Cdt> {
  using Base = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

 public:
  explicit GradedCriteria(const SizeField& field)
      : CGAL::Delaunay_mesh_criteria_2<Cdt>(kAngleBound),
        Base(kAngleBound, 0),
        field_(field) {}

  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(const SizeField& field, const Geom_traits& traits)
        : Base::Is_bad(kAngleBound, 0, traits), field_(field) {}

    using Base::Is_bad::operator();

    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& f,
                                          Quality& q) const {
      const Kernel::Point_2& a = f->vertex(0)->point();
      const Kernel::Point_2& b = f->vertex(1)->point();
      const Kernel::Point_2& c = f->vertex(2)->point();
      const Point2 centroid{(a.x() + b.x() + c.x()) / 3,
                            (a.y() + b.y() + c.y()) / 3};
      const double bound = field_(centroid);
      const double longest =
          std::max({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c),
                    CGAL::squared_distance(c, a)});
      const double size = longest / (bound * bound);
      if (size > 1) {
        q = Quality(1, size);  // the angle is not computed, as in CGAL's
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      // With a zero size bound the base class judges the angle only.
      const CGAL::Mesh_2::Face_badness badness = Base::Is_bad::operator()(f, q);
      q.second = size;
      return badness;
    }

   private:
    SizeField field_;
  };

  Is_bad is_bad_object() const { return Is_bad(field_, traits); }

 private:
  // CGAL's default: the squared sine of the smallest angle, about 20.6 deg.
  static constexpr double kAngleBound = 0.125;
  SizeField field_;
};

Kernel::Point_2 ToCgal(const Point2& p) { return {p.x, p.y}; }

// Meshes the domain under `field`; the vertices get dense ids in CGAL's
// vertex order.
void Mesh(const std::vector<Polyline>& rings, const std::vector<Point2>& seeds,
          const SizeField& field, Cdt* cdt) {
  for (const Polyline& ring : rings) {
    const size_t k = ring.points.size();
    for (size_t i = 0; i < k; ++i) {
      cdt->insert_constraint(ToCgal(ring.points[i]),
                             ToCgal(ring.points[(i + 1) % k]));
    }
  }
  std::vector<Kernel::Point_2> cgal_seeds;
  for (const Point2& s : seeds) cgal_seeds.push_back(ToCgal(s));
  CGAL::refine_Delaunay_mesh_2(*cdt, cgal_seeds.begin(), cgal_seeds.end(),
                               GradedCriteria(field));
  uint32_t id = 0;
  for (auto v = cdt->finite_vertices_begin(); v != cdt->finite_vertices_end();
       ++v) {
    v->info() = id++;
  }
}

// Replaces ds's points and triangles by the mesh's vertices (by id) and its
// in-domain faces (counter-clockwise, as CGAL keeps them).
void Export(const Cdt& cdt, Dataset* ds) {
  ds->points.assign(cdt.number_of_vertices(), Point2{});
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end();
       ++v) {
    ds->points[v->info()] = Point2{v->point().x(), v->point().y()};
  }
  auto& triangles = ds->constraints.triangles;
  triangles.clear();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    triangles.push_back(
        {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
}

}  // namespace

DomainDataset GenerateQualityMesh(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  DomainDataset out;
  out.domain_rings.push_back(NotchedSquare());
  RandomHoles(5, rng, &out.domain_rings, &out.hole_seeds);
  SizeField field{{UniformDouble(rng, 0.2, 0.8), UniformDouble(rng, 0.2, 0.6)},
                  0};
  // The point count goes as 1/scale^2: start coarse and correct the scale
  // until the count is within 3% of n (the best of a few tries).
  const double target = static_cast<double>(std::max<size_t>(n, 100));
  field.scale = 2.0 / std::sqrt(target);
  double best_error = 0;
  for (int attempt = 0; attempt < 8; ++attempt) {
    Cdt cdt;
    Mesh(out.domain_rings, out.hole_seeds, field, &cdt);
    const double count = static_cast<double>(cdt.number_of_vertices());
    const double error = std::abs(count - target) / target;
    if (attempt == 0 || error < best_error) {
      best_error = error;
      Export(cdt, &out.dataset);
    }
    if (error < 0.03) break;
    field.scale *= std::sqrt(count / target);
  }
  out.dataset.source = "mesh:" + std::to_string(n) + ":" + std::to_string(seed);
  return out;
}

}  // namespace locator::bench
