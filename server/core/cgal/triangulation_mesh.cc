// Triangulation::Builder's steps for a mesh given as triangles: its edges
// become constraints, and its triangles must then be exactly the faces they
// bound (see triangulation_builder.h).

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "server/core/cgal/triangulation.h"
#include "server/core/cgal/triangulation_builder.h"

namespace locator {

std::string Triangulation::Builder::MeshTriangleName(size_t k) const {
  const std::array<uint32_t, 3>& tri = c_.triangles[k];
  return "mesh triangle " + std::to_string(k) + " (" + std::to_string(tri[0]) +
         " " + std::to_string(tri[1]) + " " + std::to_string(tri[2]) + ")";
}

Status Triangulation::Builder::InsertMeshEdges() {
  const size_t n = t_.input_points_;
  // Every triangle's edges keyed by their merged vertex ids, then sorted:
  // the users of one edge become a run.
  struct EdgeUse {
    int64_t lo, hi;
    size_t triangle;
    bool operator<(const EdgeUse& o) const {
      return std::tie(lo, hi, triangle) < std::tie(o.lo, o.hi, o.triangle);
    }
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * c_.triangles.size());
  for (size_t k = 0; k < c_.triangles.size(); ++k) {
    const std::array<uint32_t, 3>& tri = c_.triangles[k];
    std::array<Vertex_handle, 3> v;
    for (int i = 0; i < 3; ++i) {
      if (tri[i] >= n) {
        return Status::InvalidArgument(
            MeshTriangleName(k) + ": corner index " + std::to_string(tri[i]) +
            " is out of range (" + std::to_string(n) + " points)");
      }
      v[i] = t_.by_input_[tri[i]];
    }
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
      return Status::InvalidArgument(MeshTriangleName(k) +
                                     " has repeated corners");
    }
    if (CGAL::orientation(v[0]->point(), v[1]->point(), v[2]->point()) ==
        CGAL::COLLINEAR) {
      return Status::InvalidArgument(MeshTriangleName(k) +
                                     " has collinear corners");
    }
    for (int i = 0; i < 3; ++i) {
      const auto [lo, hi] =
          std::minmax(v[i]->info().id, v[(i + 1) % 3]->info().id);
      uses.push_back({lo, hi, k});
    }
  }
  std::sort(uses.begin(), uses.end());
  for (size_t first = 0, next; first < uses.size(); first = next) {
    const EdgeUse& e = uses[first];
    next = first + 1;
    while (next < uses.size() && uses[next].lo == e.lo &&
           uses[next].hi == e.hi) {
      ++next;
    }
    const std::string edge =
        "mesh edge (" + std::to_string(e.lo) + " " + std::to_string(e.hi) + ")";
    if (next - first >= 3) {
      return Status::InvalidArgument(
          edge + " is shared by triangles " + std::to_string(e.triangle) +
          ", " + std::to_string(uses[first + 1].triangle) + " and " +
          std::to_string(uses[first + 2].triangle) + " (not a manifold)");
    }
    AddSegment(t_.by_input_[e.lo], t_.by_input_[e.hi], ConstraintKind::kMesh,
               edge + " of triangle " + std::to_string(e.triangle));
  }
  return Status::OK();
}

Status Triangulation::Builder::MarkMesh() {
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    f->info() = 0;
  }
  for (size_t k = 0; k < c_.triangles.size(); ++k) {
    std::array<uint32_t, 3> ids;
    for (int i = 0; i < 3; ++i) {
      ids[i] =
          static_cast<uint32_t>(t_.by_input_[c_.triangles[k][i]]->info().id);
    }
    const std::array<uint32_t, 3>& p = c_.triangles[k];
    if (CGAL::orientation(t_.by_input_[p[0]]->point(),
                          t_.by_input_[p[1]]->point(),
                          t_.by_input_[p[2]]->point()) == CGAL::CLOCKWISE) {
      std::swap(ids[1], ids[2]);
    }
    Face_handle f;
    if (!t_.FaceWithCorners(ids, &f)) {
      return Status::InvalidArgument(
          MeshTriangleName(k) +
          " is not a face of the triangulation of the mesh's edges: "
          "it overlaps another triangle or contains a point");
    }
    if (f->info() == 1) {
      return Status::InvalidArgument(MeshTriangleName(k) +
                                     " repeats an earlier triangle");
    }
    f->info() = 1;
  }
  return Status::OK();
}

}  // namespace locator
