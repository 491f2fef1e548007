#include "server/core/mesh/mesh_check.h"

#include <algorithm>
#include <cstring>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "common/status_macros.h"
#include "server/core/cgal/orientation.h"

namespace locator {
namespace {

constexpr uint32_t kIndexMask = ServingMesh::kIndexMask;

Status Violation(const std::string& what) {
  return Status::InvalidArgument("invalid mesh: " + what);
}

std::string FaceName(size_t f) { return "triangle " + std::to_string(f); }

uint32_t CornerOf(const ServingMesh::Arrays& a, uint32_t f, int i) {
  return a.triangles[f].corner[i] & kIndexMask;
}

Status CheckVertices(const ServingMesh::Arrays& a) {
  const size_t v = a.points.size();
  if (v < 3 || a.triangles.empty() || a.hull.size() < 3) {
    return Violation("fewer than 3 vertices, 1 triangle or 3 hull edges");
  }
  if (a.ids.size() != v || (!a.values.empty() && a.values.size() != v)) {
    return Violation("ids or values are not one per vertex");
  }
  // Input points have ids below input_points; constraint points, which are
  // vertices too, the ids after them.
  const uint64_t id_limit = a.input_points + v;
  if (a.input_points > ServingMesh::kMaxElements) {
    return Violation("input point count out of range");
  }
  if (!IsFinite({a.box.min_x, a.box.min_y}) ||
      !IsFinite({a.box.max_x, a.box.max_y})) {
    return Violation("non-finite bounding box");
  }
  for (size_t i = 0; i < v; ++i) {
    if (!IsFinite(a.points[i])) {
      return Violation("vertex " + std::to_string(i) + " is not finite");
    }
    if (a.ids[i] >= id_limit) {
      return Violation("vertex " + std::to_string(i) + " has id " +
                       std::to_string(a.ids[i]) + " out of range");
    }
  }
  return Status::OK();
}

// Checks faces [begin, end).
Status CheckFaces(const ServingMesh::Arrays& a, uint32_t begin, uint32_t end) {
  const size_t v = a.points.size(), faces = a.triangles.size();
  for (uint32_t f = begin; f < end; ++f) {
    const MeshTriangle& t = a.triangles[f];
    for (int i = 0; i < 3; ++i) {
      if ((t.corner[i] & kIndexMask) >= v) {
        return Violation(FaceName(f) + "'s corner " + std::to_string(i) +
                         " is out of range");
      }
      const uint32_t n = t.neighbor[i];
      if (ServingMesh::IsHull(n) ? (n & kIndexMask) >= a.hull.size()
                                 : n >= faces) {
        return Violation(FaceName(f) + "'s neighbour " + std::to_string(i) +
                         " is out of range");
      }
    }
    // Barycentrics divide by the area: it must be positive.
    if (Orientation(a.points[t.corner[0] & kIndexMask],
                    a.points[t.corner[1] & kIndexMask],
                    a.points[t.corner[2] & kIndexMask]) != Side::kLeft) {
      return Violation(FaceName(f) + " is not counter-clockwise");
    }
  }
  return Status::OK();
}

// CheckFaces over every face, in a slice per hardware thread (a mesh of
// 10^7 points has 2 x 10^7 faces); the first violation by face order.
Status CheckAllFaces(const ServingMesh::Arrays& a) {
  constexpr size_t kMinFacesPerThread = size_t{1} << 20;
  const auto faces = static_cast<uint32_t>(a.triangles.size());
  const size_t threads = std::clamp<size_t>(
      std::min<size_t>(std::thread::hardware_concurrency(), 8), 1,
      std::max<size_t>(faces / kMinFacesPerThread, 1));
  std::vector<Status> results(threads);
  std::vector<std::thread> workers;
  const auto slice = [&](size_t k) {
    return static_cast<uint32_t>(uint64_t{faces} * k / threads);
  };
  for (size_t k = 1; k < threads; ++k) {
    workers.emplace_back(
        [&, k] { results[k] = CheckFaces(a, slice(k), slice(k + 1)); });
  }
  results[0] = CheckFaces(a, 0, slice(1));
  for (std::thread& worker : workers) worker.join();
  for (Status& result : results) {
    if (!result.ok()) return result;
  }
  return Status::OK();
}

Status CheckHull(const ServingMesh::Arrays& a) {
  const size_t h = a.hull.size();
  for (size_t k = 0; k < h; ++k) {
    const uint32_t edge = a.hull[k], next = a.hull[(k + 1) % h];
    if (ServingMesh::EdgeFace(edge) >= a.triangles.size() ||
        ServingMesh::EdgeFace(next) >= a.triangles.size()) {
      return Violation("hull edge " + std::to_string(k) + " is out of range");
    }
    const uint32_t f = ServingMesh::EdgeFace(edge);
    const int i = ServingMesh::EdgeIndex(edge);
    if (a.triangles[f].neighbor[i] != (ServingMesh::kHullBit | k)) {
      return Violation("hull edge " + std::to_string(k) +
                       " is not a hull edge of its triangle");
    }
    // Edge i runs from corner Ccw(i) to corner Cw(i); the ring goes round
    // the hull clockwise (CGAL's circulation round the infinite vertex), so
    // each edge ends where the one before it starts.
    if (CornerOf(a, f, Ccw(i)) != CornerOf(a, ServingMesh::EdgeFace(next),
                                           Cw(ServingMesh::EdgeIndex(next)))) {
      return Violation("the hull is not a closed ring at edge " +
                       std::to_string(k));
    }
  }
  return Status::OK();
}

// Equal sizes and bytes; empty spans may have no data pointer.
template <typename T>
bool SameBytes(std::span<const T> x, std::span<const T> y) {
  return x.size() == y.size() &&
         (x.empty() || std::memcmp(x.data(), y.data(), x.size_bytes()) == 0);
}

}  // namespace

Status CompareMeshArrays(const ServingMesh::Arrays& got,
                         const ServingMesh::Arrays& want) {
  const char* differs =
      !SameBytes(got.triangles, want.triangles) ? "triangles"
      : !SameBytes(got.points, want.points)     ? "points"
      : !SameBytes(got.values, want.values)     ? "values"
      : !SameBytes(got.ids, want.ids)           ? "ids"
      : !SameBytes(got.hull, want.hull)         ? "hull"
      : got.in_domain != want.in_domain         ? "in-domain count"
      : std::memcmp(&got.box, &want.box, sizeof(got.box)) != 0 ? "box"
      : got.input_points != want.input_points ? "input point count"
      : got.digest != want.digest             ? "digest"
                                              : nullptr;
  if (differs == nullptr) return Status::OK();
  return Status::Internal(std::string("the meshes differ in their ") + differs);
}

Status CheckMeshArrays(const ServingMesh::Arrays& a) {
  RETURN_IF_ERROR(CheckVertices(a));
  if (a.in_domain == 0 || a.in_domain > a.triangles.size()) {
    return Violation("no in-domain triangle, or more than triangles");
  }
  RETURN_IF_ERROR(CheckAllFaces(a));
  return CheckHull(a);
}

}  // namespace locator
