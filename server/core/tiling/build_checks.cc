#include "server/core/tiling/build_checks.h"

#include <string>

#include "server/core/cgal/orientation.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

Status CheckPointCoordinates(std::span<const Point2> points, size_t values) {
  for (size_t i = 0; i < points.size(); ++i) {
    if (!IsFinite(points[i])) {
      return Status::InvalidArgument("point " + std::to_string(i) +
                                     " has a non-finite coordinate");
    }
  }
  if (values != 0 && values != points.size()) {
    return Status::InvalidArgument("dataset values and points differ in size");
  }
  return Status::OK();
}

Status CheckTriangulable(size_t distinct, bool all_collinear) {
  if (distinct < 3) {
    return Status::InvalidArgument(
        "dataset has " + std::to_string(distinct) +
        " distinct point(s); a triangulation needs at least 3 that are not "
        "all collinear");
  }
  if (all_collinear) {
    return Status::InvalidArgument(
        "all " + std::to_string(distinct) +
        " distinct points are collinear; no triangle can be formed");
  }
  return Status::OK();
}

Status CheckMeshSize(size_t vertices, size_t faces) {
  if (vertices <= ServingMesh::kMaxElements &&
      faces <= ServingMesh::kMaxElements) {
    return Status::OK();
  }
  return Status::InvalidArgument("the triangulation has " +
                                 std::to_string(faces) +
                                 " triangles; the serving mesh holds at most " +
                                 std::to_string(ServingMesh::kMaxElements));
}

bool AllCollinear(std::span<const Point2> points) {
  for (size_t i = 2; i < points.size(); ++i) {
    if (Orientation(points[0], points[1], points[i]) != Side::kOn) return false;
  }
  return true;
}

}  // namespace locator
