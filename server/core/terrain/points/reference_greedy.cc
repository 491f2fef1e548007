#include "server/core/terrain/points/reference_greedy.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include "server/core/terrain/grid/grid_domain.h"
#include "server/core/terrain/grid/grid_error.h"

namespace locator {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<bool, Kernel>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<
                CGAL::Triangulation_vertex_base_2<Kernel>, FaceBase>>;

// A triangle's worst sample, valid while the triangle with these corners
// is a face.
struct Entry {
  double error;
  uint64_t sample;
  std::array<Cdt::Vertex_handle, 3> corners;
  // Largest error first; ties by sample, so the order is deterministic.
  bool operator<(const Entry& o) const {
    return std::tie(error, o.sample) < std::tie(o.error, sample);
  }
};

class ReferenceBuilder {
 public:
  ReferenceBuilder(const ElevationGrid& grid, const CellMask& mask)
      : grid_(grid), mask_(mask) {}

  void Run(double max_error, uint64_t max_points, ReferenceTin* out) {
    std::vector<GridPoint> points;
    std::vector<std::pair<size_t, size_t>> runs;
    TraceBoundary(
        mask_,
        GridRect{0, 0, grid_.width - int64_t{1}, grid_.height - int64_t{1}}, {},
        &points, &runs);
    std::vector<Kernel::Point_2> cgal_points;
    for (const GridPoint& p : points) {
      cgal_points.emplace_back(static_cast<double>(p.x),
                               static_cast<double>(p.y));
    }
    cdt_.insert_constraints(cgal_points.begin(), cgal_points.end(),
                            runs.begin(), runs.end());
    for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end();
         ++f) {
      Queue(f);
    }
    while (!queue_.empty()) {
      const Entry top = queue_.top();
      Cdt::Face_handle face;
      if (!cdt_.tds().is_face(top.corners[0], top.corners[1], top.corners[2],
                              face)) {
        queue_.pop();  // stale: the triangle is gone
        continue;
      }
      if (top.error <= max_error ||
          (max_points > 0 && cdt_.number_of_vertices() >= max_points)) {
        break;
      }
      queue_.pop();
      const Cdt::Vertex_handle v = cdt_.insert(
          Kernel::Point_2(static_cast<double>(top.sample % grid_.width),
                          static_cast<double>(top.sample / grid_.width)),
          face);
      // Every face the insertion made has the new vertex as a corner.
      auto around = cdt_.incident_faces(v);
      const auto end = around;
      do {
        if (!cdt_.is_infinite(around)) Queue(around);
      } while (++around != end);
    }
    out->vertices = cdt_.number_of_vertices();
    out->max_error = 0;
    while (!queue_.empty()) {
      const Entry& top = queue_.top();
      Cdt::Face_handle face;
      if (cdt_.tds().is_face(top.corners[0], top.corners[1], top.corners[2],
                             face)) {
        out->max_error = top.error;
        break;
      }
      queue_.pop();
    }
    for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end();
         ++f) {
      if (!InDomain(f)) continue;
      std::array<uint64_t, 3> triangle;
      for (int i = 0; i < 3; ++i) {
        triangle[i] =
            static_cast<uint64_t>(f->vertex(i)->point().y()) * grid_.width +
            static_cast<uint64_t>(f->vertex(i)->point().x());
      }
      out->triangles.push_back(triangle);
    }
  }

 private:
  std::array<GridPoint, 3> Corners(Cdt::Face_handle f) const {
    std::array<GridPoint, 3> c;
    for (int i = 0; i < 3; ++i) {
      c[i] = GridPoint{static_cast<int64_t>(f->vertex(i)->point().x()),
                       static_cast<int64_t>(f->vertex(i)->point().y())};
    }
    return c;
  }
  // The cell at the centroid is in the domain (see BuildRegionMesh).
  bool InDomain(Cdt::Face_handle f) const {
    const std::array<GridPoint, 3> c = Corners(f);
    return mask_.Valid((c[0].x + c[1].x + c[2].x) / 3,
                       (c[0].y + c[1].y + c[2].y) / 3);
  }
  void Queue(Cdt::Face_handle f) {
    if (!InDomain(f)) return;
    const WorstSample worst =
        WorstPlaneSample(grid_, Corners(f), {false, false, false});
    if (worst.error > 0) {
      queue_.push(Entry{worst.error,
                        worst.sample,
                        {f->vertex(0), f->vertex(1), f->vertex(2)}});
    }
  }

  const ElevationGrid& grid_;
  const CellMask& mask_;
  Cdt cdt_;
  std::priority_queue<Entry> queue_;
};

}  // namespace

Status ReferenceGreedyGrid(const ElevationGrid& grid, double max_error,
                           uint64_t max_points, ReferenceTin* out) {
  *out = ReferenceTin();
  if (grid.width < 2 || grid.height < 2 ||
      grid.values.size() != grid.samples()) {
    return Status::InvalidArgument("the grid has no cell");
  }
  const CellMask mask(grid);
  if (mask.valid_cells() == 0) {
    return Status::InvalidArgument(
        "no cell of the grid has four valid corners");
  }
  ReferenceBuilder(grid, mask).Run(max_error, max_points, out);
  return Status::OK();
}

}  // namespace locator
