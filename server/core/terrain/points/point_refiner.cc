#include "server/core/terrain/points/point_refiner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "common/status_macros.h"
#include "server/core/cgal/orientation.h"
#include "server/core/geometry/barycentric.h"

namespace locator {

namespace {

// Insertions between two progress updates.
constexpr uint64_t kProgressEvery = 256;

// Whether p lies in the closed counter-clockwise triangle a, b, c.
bool Contains(const Point2& a, const Point2& b, const Point2& c,
              const Point2& p) {
  return Orientation(a, b, p) != Side::kRight &&
         Orientation(b, c, p) != Side::kRight &&
         Orientation(c, a, p) != Side::kRight;
}

}  // namespace

PointRefiner::PointRefiner(std::span<const Point2> points,
                           std::span<const double> values, TinMesh* mesh,
                           std::vector<double>* vertex_values, double target)
    : points_(points),
      values_(values),
      mesh_(mesh),
      vertex_values_(vertex_values),
      target_(target),
      first_inserted_(static_cast<uint32_t>(mesh->num_vertices())),
      next_(points.size(), kNone) {
  head_.resize(mesh->num_triangles(), kNone);
  candidate_.resize(mesh->num_triangles(), kNone);
  error_.resize(mesh->num_triangles(), 0);
}

void PointRefiner::Add(uint32_t i, uint32_t t) {
  next_[i] = head_[t];
  head_[t] = i;
}

void PointRefiner::SetRepeats(uint32_t i, double lo, double hi) {
  repeats_[i] = {lo, hi};
}

void PointRefiner::AddAtVertex(uint32_t v, double lo, double hi) {
  const double z = (*vertex_values_)[v];
  vertex_error_ = std::max({vertex_error_, std::abs(lo - z), std::abs(hi - z)});
}

double PointRefiner::PointError(uint32_t i, double v) const {
  if (const auto it = repeats_.find(i); it != repeats_.end()) {
    return std::max(std::abs(it->second.first - v),
                    std::abs(it->second.second - v));
  }
  return std::abs(values_[i] - v);
}

double PointRefiner::SurfaceAt(uint32_t t, uint32_t i) const {
  const std::array<Point2, 3> corners = {mesh_->point(mesh_->Corner(t, 0)),
                                         mesh_->point(mesh_->Corner(t, 1)),
                                         mesh_->point(mesh_->Corner(t, 2))};
  const Point2& p = points_[i];
  std::array<double, 3> b{};
  bool on_edge = false;
  if (measure_ == PointMeasure::kServed) {
    // Mesh edge k runs from corner k to k + 1, opposite corner k + 2: the
    // engine names an edge by its opposite corner.
    for (int k = 0; k < 3 && !on_edge; ++k) {
      if (Orientation(corners[k], corners[(k + 1) % 3], p) == Side::kOn) {
        b = EdgeBarycentric(corners, (k + 2) % 3, p);
        on_edge = true;
      }
    }
  }
  if (!on_edge) b = Barycentric(corners[0], corners[1], corners[2], p);
  double value = 0;
  for (int k = 0; k < 3; ++k) {
    value += b[k] * (*vertex_values_)[mesh_->Corner(t, k)];
  }
  return value;
}

void PointRefiner::Rescan(uint32_t t) {
  uint32_t worst = kNone;
  double worst_error = 0;
  for (uint32_t i = head_[t]; i != kNone; i = next_[i]) {
    const double e = PointError(i, SurfaceAt(t, i));
    if (worst == kNone || e > worst_error) {
      worst = i;
      worst_error = e;
    }
  }
  candidate_[t] = worst;
  error_[t] = worst_error;
  if (worst != kNone && worst_error > target_) {
    queue_.Set(t, worst_error);
  } else {
    queue_.Remove(t);
  }
}

void PointRefiner::ScanAll(PointMeasure measure) {
  measure_ = measure;
  queue_.Clear();
  for (uint32_t t = 0; t < mesh_->num_triangles(); ++t) {
    if (mesh_->tag(t) == 1) Rescan(t);
  }
}

Status PointRefiner::Rebucket(uint32_t inserted_point) {
  const std::vector<uint32_t>& touched = mesh_->touched();
  pool_.clear();
  for (const uint32_t t : touched) {
    for (uint32_t i = head_[t]; i != kNone; i = next_[i]) {
      if (i != inserted_point) pool_.push_back(i);
    }
    head_[t] = kNone;
  }
  for (const uint32_t i : pool_) {
    // The touched triangles cover what they covered before; a point on
    // the domain's boundary goes to the triangle inside it.
    uint32_t home = kNone;
    for (const uint32_t t : touched) {
      if (mesh_->tag(t) != 1) continue;
      if (Contains(mesh_->point(mesh_->Corner(t, 0)),
                   mesh_->point(mesh_->Corner(t, 1)),
                   mesh_->point(mesh_->Corner(t, 2)), points_[i])) {
        home = t;
        break;
      }
    }
    if (home == kNone) {
      return Status::Internal("greedy insertion lost point " +
                              std::to_string(i));
    }
    Add(i, home);
  }
  return Status::OK();
}

Status PointRefiner::Refine(uint64_t max_vertices,
                            TinProgressReporter* progress) {
  uint64_t inserted = 0;
  while (!queue_.empty() &&
         (max_vertices == 0 || mesh_->num_vertices() < max_vertices)) {
    const uint32_t t = queue_.Pop();
    const uint32_t i = candidate_[t];
    const uint32_t v = mesh_->AddVertex(points_[i]);
    vertex_values_->push_back(values_[i]);
    inserted_.push_back(i);
    if (!mesh_->Insert(v, t)) {
      return Status::Internal("greedy insertion: point " + std::to_string(i) +
                              " is not inside its triangle");
    }
    if (const auto it = repeats_.find(i); it != repeats_.end()) {
      AddAtVertex(v, it->second.first, it->second.second);
    }
    head_.resize(mesh_->num_triangles(), kNone);
    candidate_.resize(mesh_->num_triangles(), kNone);
    error_.resize(mesh_->num_triangles(), 0);
    RETURN_IF_ERROR(Rebucket(i));
    for (const uint32_t u : mesh_->touched()) {
      if (mesh_->tag(u) == 1) Rescan(u);
    }
    if (++inserted % kProgressEvery == 0 && progress != nullptr &&
        !queue_.empty()) {
      progress->Update(0, mesh_->num_vertices(), queue_.TopError());
    }
  }
  if (progress != nullptr) {
    progress->Update(0, mesh_->num_vertices(), MaxError());
  }
  return Status::OK();
}

double PointRefiner::MaxError() const {
  double largest = vertex_error_;
  if (!queue_.empty()) return std::max(largest, queue_.TopError());
  for (uint32_t t = 0; t < error_.size(); ++t) {
    if (mesh_->tag(t) == 1) largest = std::max(largest, error_[t]);
  }
  return largest;
}

}  // namespace locator
