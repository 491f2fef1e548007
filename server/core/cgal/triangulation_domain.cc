// Triangulation::Builder's last steps: which faces are in the domain (ring
// nesting depth, Triangle's segment and hole rules) and the ids of the
// in-domain triangles (see triangulation_builder.h); and which edges are
// breaklines, by the kinds of the constraints along them.

#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "common/input_text.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/cgal/triangulation_builder.h"

namespace locator {

bool Triangulation::AlongBreakline(Face_handle f, int i) const {
  if (!f->is_constrained(i)) return false;
  const Vertex_handle a = f->vertex(Cdt::cw(i));
  const Vertex_handle b = f->vertex(Cdt::ccw(i));
  for (auto c = dt_.contexts_begin(a, b); c != dt_.contexts_end(a, b); ++c) {
    const ConstraintKind kind = constraint_kinds_.at(c->id());
    if (kind == ConstraintKind::kBreakline ||
        kind == ConstraintKind::kSegment) {
      return true;
    }
  }
  return false;
}

int Triangulation::Builder::RingCount(Face_handle f, int i) const {
  if (!f->is_constrained(i)) return 0;
  const Vertex_handle a = f->vertex(Cdt::cw(i));
  const Vertex_handle b = f->vertex(Cdt::ccw(i));
  int rings = 0;
  for (auto c = dt_.contexts_begin(a, b); c != dt_.contexts_end(a, b); ++c) {
    if (t_.constraint_kinds_.at(c->id()) == ConstraintKind::kRing) ++rings;
  }
  return rings;
}

bool Triangulation::Builder::IsBarrier(Face_handle f, int i) const {
  if (!f->is_constrained(i)) return false;
  const Vertex_handle a = f->vertex(Cdt::cw(i));
  const Vertex_handle b = f->vertex(Cdt::ccw(i));
  for (auto c = dt_.contexts_begin(a, b); c != dt_.contexts_end(a, b); ++c) {
    if (t_.constraint_kinds_.at(c->id()) != ConstraintKind::kBreakline) {
      return true;
    }
  }
  return false;
}

void Triangulation::Builder::MarkRingDepth() {
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    f->info() = -1;
  }
  // Flood each region at its depth; crossing a ring edge enters the region
  // beyond at depth + (rings along that edge). Regions are taken in the
  // order they are found, which is breadth-first by depth.
  std::deque<std::pair<Face_handle, int64_t>> regions;
  regions.emplace_back(dt_.infinite_face(), 0);
  std::vector<Face_handle> stack;
  while (!regions.empty()) {
    const auto [seed, depth] = regions.front();
    regions.pop_front();
    if (seed->info() != -1) continue;
    seed->info() = depth;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = f->neighbor(i);
        if (n->info() != -1) continue;
        const int rings = RingCount(f, i);
        if (rings > 0) {
          regions.emplace_back(n, depth + rings);
        } else {
          n->info() = depth;
          stack.push_back(n);
        }
      }
    }
  }
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    f->info() = dt_.is_infinite(f) ? 0 : f->info() % 2;
  }
}

void Triangulation::Builder::Eat(Face_handle seed) {
  std::vector<Face_handle> stack = {seed};
  seed->info() = 0;
  while (!stack.empty()) {
    const Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const Face_handle n = f->neighbor(i);
      if (n->info() == 0 || IsBarrier(f, i)) continue;
      n->info() = 0;
      stack.push_back(n);
    }
  }
}

Status Triangulation::Builder::EatSegmentRegions() {
  // Triangle's rule: what is reachable from outside the hull is out.
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    if (dt_.is_infinite(f)) {
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = f->neighbor(i);
        if (!dt_.is_infinite(n) && n->info() != 0 && !IsBarrier(f, i)) Eat(n);
      }
    }
  }
  for (size_t k = 0; k < c_.hole_seeds.size(); ++k) {
    const Point2& p = c_.hole_seeds[k];
    const std::string name =
        "hole point " + std::to_string(k) + " " + PointText(p);
    if (!IsFinite(p)) {
      return Status::InvalidArgument(name + " has a non-finite coordinate");
    }
    const Face_handle f = dt_.locate(ToCgal(p));
    if (dt_.is_infinite(f) || f->info() == 0) {
      return Status::InvalidArgument(
          name +
          " is outside every region bounded by the rings and "
          "segments");
    }
    Eat(f);
  }
  return Status::OK();
}

Status Triangulation::Builder::MarkDomain() {
  if (!c_.triangles.empty()) {
    t_.has_domain_ = true;
    return MarkMesh();
  }
  if (c_.rings.empty() && c_.segments.empty() && c_.hole_seeds.empty()) {
    for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
      f->info() = dt_.is_infinite(f) ? 0 : 1;
    }
    return Status::OK();
  }
  t_.has_domain_ = true;
  if (c_.rings.empty()) {
    for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
      f->info() = dt_.is_infinite(f) ? 0 : 1;
    }
  } else {
    MarkRingDepth();
  }
  if (c_.segments.empty() && c_.hole_seeds.empty()) return Status::OK();
  return EatSegmentRegions();
}

Status Triangulation::Builder::NumberTriangles() {
  int64_t next_id = 0;
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    if (dt_.is_infinite(f) || f->info() != 1) f->info() = -1;
  }
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    if (f->info() == 1) f->info() = next_id++;
  }
  t_.num_triangles_ = static_cast<size_t>(next_id);
  if (next_id == 0) {
    return Status::InvalidArgument(
        "the domain is empty: no triangle is inside its boundary");
  }
  t_.num_holes_ = CountHoles();
  return Status::OK();
}

size_t Triangulation::Builder::CountHoles() {
  // Out-of-domain faces carry info -1; a region is marked -2 while flooded
  // and set back to -1 after, so no side table is needed.
  constexpr int64_t kSeen = -2;
  size_t holes = 0;
  std::vector<Face_handle> region;
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    if (f->info() != -1) continue;
    bool touches_hull = false;
    region.assign(1, f);
    f->info() = kSeen;
    for (size_t k = 0; k < region.size(); ++k) {
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = region[k]->neighbor(i);
        if (dt_.is_infinite(n)) {
          touches_hull = true;
        } else if (n->info() == -1) {
          n->info() = kSeen;
          region.push_back(n);
        }
      }
    }
    if (!touches_hull) ++holes;
  }
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    if (f->info() == kSeen) f->info() = -1;
  }
  return holes;
}

}  // namespace locator
