#include "server/core/terrain/tin_mesh.h"

#include <utility>
#include <vector>

#include "server/core/geometry/circle.h"

namespace locator {

uint32_t TinMesh::AddVertex(const Point2& p) {
  points_.push_back(p);
  return static_cast<uint32_t>(points_.size() - 1);
}

Side TinMesh::Orient(uint32_t a, uint32_t b, uint32_t c) const {
  if (!integers_) return Orientation(points_[a], points_[b], points_[c]);
  const Point2 &pa = points_[a], &pb = points_[b], &pc = points_[c];
  const auto ax = static_cast<int64_t>(pa.x) - static_cast<int64_t>(pc.x);
  const auto ay = static_cast<int64_t>(pa.y) - static_cast<int64_t>(pc.y);
  const auto bx = static_cast<int64_t>(pb.x) - static_cast<int64_t>(pc.x);
  const auto by = static_cast<int64_t>(pb.y) - static_cast<int64_t>(pc.y);
  const int64_t det = ax * by - ay * bx;  // |terms| < 2^50
  return det > 0 ? Side::kLeft : (det < 0 ? Side::kRight : Side::kOn);
}

bool TinMesh::InCircle(uint32_t a, uint32_t b, uint32_t c, uint32_t d) const {
  if (!integers_) {
    return InsideCircumcircle(points_[a], points_[b], points_[c], points_[d]);
  }
  // The lifted determinant relative to d: differences below 2^25, lifts
  // below 2^51, so every product fits in 128 bits.
  const Point2& pd = points_[d];
  const auto dx = static_cast<int64_t>(pd.x), dy = static_cast<int64_t>(pd.y);
  int64_t x[3], y[3];
  __int128 lift[3];
  const uint32_t corners[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    x[i] = static_cast<int64_t>(points_[corners[i]].x) - dx;
    y[i] = static_cast<int64_t>(points_[corners[i]].y) - dy;
    lift[i] = static_cast<__int128>(x[i] * x[i] + y[i] * y[i]);
  }
  const __int128 det = lift[0] * (x[1] * y[2] - x[2] * y[1]) +
                       lift[1] * (x[2] * y[0] - x[0] * y[2]) +
                       lift[2] * (x[0] * y[1] - x[1] * y[0]);
  return det > 0;
}

uint32_t TinMesh::AddTriangle(uint32_t a, uint32_t b, uint32_t c, uint8_t tag) {
  const auto t = static_cast<uint32_t>(num_triangles());
  constexpr uint32_t kBoundary = kNoTwin | kConstrainedBit;
  records_.push_back(
      Record{{a, b, c}, {kBoundary, kBoundary, kBoundary}, 0, tag});
  return t;
}

void TinMesh::Link(uint32_t h, uint32_t g) {
  RawTwin(h) = g;
  RawTwin(g) = h;
}

void TinMesh::Constrain(uint32_t h) {
  RawTwin(h) |= kConstrainedBit;
  if (Twin(h) != kNoTwin) RawTwin(Twin(h)) |= kConstrainedBit;
}

void TinMesh::Touch(uint32_t t) {
  if (records_[t].stamp == stamp_) return;
  records_[t].stamp = stamp_;
  touched_.push_back(t);
}

uint32_t TinMesh::SetTriangle(uint32_t t, uint32_t a, uint32_t b, uint32_t c,
                              std::array<uint32_t, 3> twins, uint8_t tag) {
  Record& record = records_[t];
  record.corner[0] = a;
  record.corner[1] = b;
  record.corner[2] = c;
  record.tag = tag;
  for (uint32_t i = 0; i < 3; ++i) {
    record.twin[i] = twins[i];
    const uint32_t twin = twins[i] & kTwinMask;
    if (twin != kNoTwin) {
      RawTwin(twin) = (3 * t + i) | (twins[i] & kConstrainedBit);
    }
  }
  Touch(t);
  return t;
}

bool TinMesh::Insert(uint32_t v, uint32_t t) {
  ++stamp_;
  touched_.clear();
  int on_edge = -1;
  for (int i = 0; i < 3; ++i) {
    const Side side = Orient(Corner(t, i), Corner(t, (i + 1) % 3), v);
    if (side == Side::kRight) return false;
    if (side == Side::kOn) {
      if (on_edge >= 0) return false;  // v is a corner
      on_edge = i;
    }
  }
  if (on_edge >= 0) {
    InsertOnEdge(v, 3 * t + on_edge);
  } else {
    InsertInTriangle(v, t);
  }
  return true;
}

void TinMesh::InsertInTriangle(uint32_t v, uint32_t t) {
  const uint32_t a = Corner(t, 0), b = Corner(t, 1), c = Corner(t, 2);
  const uint32_t ab = RawTwin(3 * t), bc = RawTwin(3 * t + 1),
                 ca = RawTwin(3 * t + 2);
  const uint8_t t_tag = tag(t);
  const auto t1 = static_cast<uint32_t>(num_triangles());
  const uint32_t t2 = t1 + 1;
  // The new triangles exist before any twin points at them.
  AddTriangle(b, c, v, t_tag);
  AddTriangle(c, a, v, t_tag);
  SetTriangle(t, a, b, v, {ab, 3 * t1 + 2, 3 * t2 + 1}, t_tag);
  SetTriangle(t1, b, c, v, {bc, 3 * t2 + 2, 3 * t + 1}, t_tag);
  SetTriangle(t2, c, a, v, {ca, 3 * t + 2, 3 * t1 + 1}, t_tag);
  Legalize(3 * t);
  Legalize(3 * t1);
  Legalize(3 * t2);
}

void TinMesh::InsertOnEdge(uint32_t v, uint32_t h) {
  // t = (a, b, c) with h = a -> b; its twin g = b -> a in u = (b, a, d).
  const uint32_t t = TriangleOf(h);
  const uint32_t a = Origin(h), b = Origin(Next(h)), c = Origin(Prev(h));
  const uint32_t bc = RawTwin(Next(h)), ca = RawTwin(Prev(h));
  const uint32_t cut = RawTwin(h) & kConstrainedBit;
  const uint32_t g = Twin(h);
  const uint8_t t_tag = tag(t);
  const auto t1 = static_cast<uint32_t>(num_triangles());
  AddTriangle(c, v, b, t_tag);
  if (g == kNoTwin) {
    // A boundary edge: t becomes (c, a, v) and (c, v, b).
    SetTriangle(t, c, a, v, {ca, kNoTwin | cut, 3 * t1}, t_tag);
    SetTriangle(t1, c, v, b, {3 * t + 2, kNoTwin | cut, bc}, t_tag);
    Legalize(3 * t);
    Legalize(3 * t1 + 2);
    return;
  }
  const uint32_t u = TriangleOf(g);
  const uint32_t d = Origin(Prev(g));
  const uint32_t ad = RawTwin(Next(g)), db = RawTwin(Prev(g));
  const uint8_t u_tag = tag(u);
  const uint32_t u1 = t1 + 1;
  AddTriangle(d, v, a, u_tag);
  SetTriangle(t, c, a, v, {ca, (3 * u1 + 1) | cut, 3 * t1}, t_tag);
  SetTriangle(t1, c, v, b, {3 * t + 2, (3 * u + 1) | cut, bc}, t_tag);
  SetTriangle(u, d, b, v, {db, (3 * t1 + 1) | cut, 3 * u1}, u_tag);
  SetTriangle(u1, d, v, a, {3 * u + 2, (3 * t + 1) | cut, ad}, u_tag);
  Legalize(3 * t);
  Legalize(3 * t1 + 2);
  Legalize(3 * u);
  Legalize(3 * u1 + 2);
}

void TinMesh::Legalize(uint32_t start) {
  pending_.assign(1, start);
  while (!pending_.empty()) {
    // h = p -> q in t = (p, q, r), r the new vertex; its twin q -> p in
    // u = (q, p, s).
    const uint32_t h = pending_.back();
    pending_.pop_back();
    if (IsConstrained(h)) continue;  // boundary edges are constrained too
    const uint32_t g = Twin(h);
    const uint32_t t = TriangleOf(h), u = TriangleOf(g);
    const uint32_t p = Origin(h), q = Origin(Next(h)), r = Origin(Prev(h));
    const uint32_t s = Origin(Prev(g));
    if (!InCircle(p, q, r, s)) continue;
    // The quadrilateral p, s, q, r is convex in a Delaunay mesh; a mesh
    // that is not (stitched tiles) keeps a reflex one unflipped.
    if (Orient(r, p, s) != Side::kLeft || Orient(s, q, r) != Side::kLeft) {
      continue;
    }
    const uint32_t rp = RawTwin(Prev(h)), qr = RawTwin(Next(h));
    const uint32_t ps = RawTwin(Next(g)), sq = RawTwin(Prev(g));
    SetTriangle(t, r, p, s, {rp, ps, 3 * u + 2}, tag(t));
    SetTriangle(u, s, q, r, {sq, qr, 3 * t + 2}, tag(u));
    pending_.push_back(3 * t + 1);  // p -> s, opposite r
    pending_.push_back(3 * u);      // s -> q, opposite r
  }
}

void TinMesh::Renumber(std::span<const uint32_t> vertex_order,
                       std::span<const uint32_t> triangle_order) {
  std::vector<uint32_t> vertex_index(points_.size());
  LargeVector<Point2> points;
  points.reserve(points_.size());
  for (uint32_t k = 0; k < vertex_order.size(); ++k) {
    vertex_index[vertex_order[k]] = k;
    points.push_back(points_[vertex_order[k]]);
  }
  points_ = std::move(points);
  std::vector<uint32_t> triangle_index(records_.size());
  for (uint32_t k = 0; k < triangle_order.size(); ++k) {
    triangle_index[triangle_order[k]] = k;
  }
  LargeVector<Record> records;
  records.reserve(records_.size());
  for (const uint32_t old : triangle_order) {
    Record r = records_[old];
    for (int i = 0; i < 3; ++i) {
      r.corner[i] = vertex_index[r.corner[i]];
      const uint32_t twin = r.twin[i] & kTwinMask;
      if (twin != kNoTwin) {
        r.twin[i] = (3 * triangle_index[twin / 3] + twin % 3) |
                    (r.twin[i] & kConstrainedBit);
      }
    }
    r.stamp = 0;
    records.push_back(r);
  }
  records_ = std::move(records);
  touched_.clear();
  stamp_ = 0;
}

void TinMesh::ShrinkToFit() {
  points_.shrink_to_fit();
  records_.shrink_to_fit();
}

void TinMesh::Reserve(size_t triangles, size_t vertices) {
  points_.reserve(vertices);
  records_.reserve(triangles);
}

size_t TinMesh::MemoryBytes() const {
  return points_.capacity() * sizeof(Point2) +
         records_.capacity() * sizeof(Record);
}

}  // namespace locator
