#include "server/core/patch/clipped_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

namespace locator {
namespace {

// The clip lines in the order they are applied.
constexpr std::array<BoxSide, 4> kSides = {kWestSide, kSouthSide, kEastSide,
                                           kNorthSide};

bool IsVertical(BoxSide side) { return side == kWestSide || side == kEastSide; }

// What a vertex of a clipped piece is, which names it across the pieces
// of one box: a patch vertex (a = its index), a TIN edge crossing a side
// (a, b: the edge's ends, in key order; side), or a box corner (side: the
// two sides' bits).
struct VertexKey {
  enum Kind : uint8_t { kPatchVertex, kCrossing, kCorner } kind;
  uint32_t a = 0, b = 0;
  uint8_t side = 0;
  bool operator<(const VertexKey& o) const {
    return std::tie(kind, a, b, side) < std::tie(o.kind, o.a, o.b, o.side);
  }
  bool operator==(const VertexKey& o) const {
    return kind == o.kind && a == o.a && b == o.b && side == o.side;
  }
};

struct PieceVertex {
  Point2 p;
  double h;
  VertexKey key;
  // What the edge to the next vertex lies on: a TIN edge (its ends as
  // patch indices, in key order) or a clip line (edge_side != 0).
  uint32_t edge_a = 0, edge_b = 0;
  uint8_t edge_side = 0;
};

class TriangleClipper {
 public:
  TriangleClipper(const MeshPatch& patch, const BoundingBox& box)
      : patch_(patch), box_(box) {}

  // The piece of triangle `t` (counter-clockwise) inside the box.
  std::vector<PieceVertex> Clip(const std::array<uint32_t, 3>& t) const {
    std::vector<PieceVertex> piece;
    for (int i = 0; i < 3; ++i) {
      const uint32_t v = t[i], w = t[(i + 1) % 3];
      const auto [a, b] = InKeyOrder(v, w);
      piece.push_back(PieceVertex{.p = patch_.points[v],
                                  .h = patch_.heights[v],
                                  .key = {VertexKey::kPatchVertex, v},
                                  .edge_a = a,
                                  .edge_b = b});
    }
    for (BoxSide side : kSides) {
      if (piece.empty()) break;
      std::vector<PieceVertex> kept;
      for (size_t i = 0; i < piece.size(); ++i) {
        const PieceVertex& p = piece[i];
        const PieceVertex& q = piece[(i + 1) % piece.size()];
        const bool p_in = Inside(side, p.p), q_in = Inside(side, q.p);
        if (p_in) kept.push_back(p);
        if (p_in != q_in) {
          PieceVertex cut = Cut(p, side, t);
          if (p_in) {  // leaving: the piece goes on along the clip line
            cut.edge_side = side;
          } else {  // entering: on along the edge it entered by
            cut.edge_a = p.edge_a, cut.edge_b = p.edge_b;
            cut.edge_side = p.edge_side;
          }
          kept.push_back(cut);
        }
      }
      // A vertex on the line is both kept and cut: keep it once, with the
      // edge that leaves the later of the two (the ring goes on from it).
      std::vector<PieceVertex> unique;
      for (const PieceVertex& v : kept) {
        if (!unique.empty() && unique.back().key == v.key) {
          unique.back().edge_a = v.edge_a;
          unique.back().edge_b = v.edge_b;
          unique.back().edge_side = v.edge_side;
        } else {
          unique.push_back(v);
        }
      }
      while (unique.size() > 1 && unique.front().key == unique.back().key) {
        unique.pop_back();
      }
      piece = std::move(unique);
    }
    return piece;
  }

 private:
  std::pair<uint32_t, uint32_t> InKeyOrder(uint32_t v, uint32_t w) const {
    return patch_.keys[v] < patch_.keys[w] ||
                   (patch_.keys[v] == patch_.keys[w] && v < w)
               ? std::pair(v, w)
               : std::pair(w, v);
  }

  double Line(BoxSide side) const {
    switch (side) {
      case kWestSide:
        return box_.min_x;
      case kSouthSide:
        return box_.min_y;
      case kEastSide:
        return box_.max_x;
      case kNorthSide:
        return box_.max_y;
    }
    return 0;
  }

  bool Inside(BoxSide side, const Point2& p) const {
    switch (side) {
      case kWestSide:
        return p.x >= box_.min_x;
      case kSouthSide:
        return p.y >= box_.min_y;
      case kEastSide:
        return p.x <= box_.max_x;
      case kNorthSide:
        return p.y <= box_.max_y;
    }
    return false;
  }

  // Where the edge leaving `p` crosses the line of `side`, computed from
  // what the edge lies on (not from p, which may itself be a cut), so that
  // every box sharing the line gets the same point.
  PieceVertex Cut(const PieceVertex& p, BoxSide side,
                  const std::array<uint32_t, 3>& t) const {
    const double line = Line(side);
    PieceVertex cut;
    if (p.edge_side != 0) {
      // Along a perpendicular clip line: the box's corner.
      const uint8_t corner = p.edge_side | side;
      cut.p = IsVertical(side) ? Point2{line, Line(BoxSide(p.edge_side))}
                               : Point2{Line(BoxSide(p.edge_side)), line};
      cut.h = HeightInTriangle(t, cut.p);
      cut.key = {VertexKey::kCorner, 0, 0, corner};
      return cut;
    }
    const uint32_t a = p.edge_a, b = p.edge_b;
    const Point2& pa = patch_.points[a];
    const Point2& pb = patch_.points[b];
    const double ca = IsVertical(side) ? pa.x : pa.y;
    const double cb = IsVertical(side) ? pb.x : pb.y;
    // An end on the line is the crossing itself.
    for (uint32_t end : {a, b}) {
      if ((end == a ? ca : cb) == line) {
        return PieceVertex{.p = patch_.points[end],
                           .h = patch_.heights[end],
                           .key = {VertexKey::kPatchVertex, end}};
      }
    }
    const double s = (line - ca) / (cb - ca);
    const double other =
        IsVertical(side) ? pa.y + s * (pb.y - pa.y) : pa.x + s * (pb.x - pa.x);
    cut.p = IsVertical(side) ? Point2{line, other} : Point2{other, line};
    cut.h = patch_.heights[a] + s * (patch_.heights[b] - patch_.heights[a]);
    cut.key = {VertexKey::kCrossing, a, b, side};
    return cut;
  }

  // The linear value at `q` of triangle `t`, from its corners in key
  // order.
  double HeightInTriangle(const std::array<uint32_t, 3>& t,
                          const Point2& q) const {
    std::array<uint32_t, 3> c = t;
    std::sort(c.begin(), c.end(), [&](uint32_t v, uint32_t w) {
      return InKeyOrder(v, w).first == v && v != w;
    });
    const Point2 &p0 = patch_.points[c[0]], &p1 = patch_.points[c[1]],
                 &p2 = patch_.points[c[2]];
    const double det =
        (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
    const double b1 =
        ((q.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (q.y - p0.y)) / det;
    const double b2 =
        ((p1.x - p0.x) * (q.y - p0.y) - (q.x - p0.x) * (p1.y - p0.y)) / det;
    const double h0 = patch_.heights[c[0]];
    return h0 + b1 * (patch_.heights[c[1]] - h0) +
           b2 * (patch_.heights[c[2]] - h0);
  }

  const MeshPatch& patch_;
  const BoundingBox& box_;
};

double Area2(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

}  // namespace

ClippedMesh ClipMeshToBox(const MeshPatch& patch, const BoundingBox& box) {
  ClippedMesh out;
  // Patch vertices by index (most of a tile's), the points the clip makes
  // by key.
  constexpr uint32_t kUnused = 0xffffffffu;
  std::vector<uint32_t> patch_vertex(patch.size(), kUnused);
  std::map<VertexKey, uint32_t> made;
  const auto add = [&](const PieceVertex& v) {
    uint32_t* slot = v.key.kind == VertexKey::kPatchVertex
                         ? &patch_vertex[v.key.a]
                         : &made.emplace(v.key, kUnused).first->second;
    if (*slot == kUnused) {
      *slot = static_cast<uint32_t>(out.size());
      uint8_t sides = 0;
      if (v.p.x == box.min_x) sides |= kWestSide;
      if (v.p.y == box.min_y) sides |= kSouthSide;
      if (v.p.x == box.max_x) sides |= kEastSide;
      if (v.p.y == box.max_y) sides |= kNorthSide;
      out.points.push_back(v.p);
      out.heights.push_back(v.h);
      out.sides.push_back(sides);
      out.edges.push_back(v.key.kind == VertexKey::kCrossing
                              ? std::array<uint32_t, 2>{v.key.a, v.key.b}
                              : std::array<uint32_t, 2>{ClippedMesh::kNoEdge,
                                                        ClippedMesh::kNoEdge});
    }
    return *slot;
  };
  const TriangleClipper clipper(patch, box);
  for (std::array<uint32_t, 3> t : patch.triangles) {
    const Point2 &a = patch.points[t[0]], &b = patch.points[t[1]],
                 &c = patch.points[t[2]];
    if (!IsFinite(a) || !IsFinite(b) || !IsFinite(c)) continue;
    if (!std::isfinite(patch.heights[t[0]] + patch.heights[t[1]] +
                       patch.heights[t[2]])) {
      continue;
    }
    const double area = Area2(a, b, c);
    if (area == 0 || std::isnan(area)) continue;
    if (area < 0) std::swap(t[1], t[2]);
    if (std::max({a.x, b.x, c.x}) < box.min_x ||
        std::min({a.x, b.x, c.x}) > box.max_x ||
        std::max({a.y, b.y, c.y}) < box.min_y ||
        std::min({a.y, b.y, c.y}) > box.max_y) {
      continue;
    }
    if (box.Contains(a) && box.Contains(b) && box.Contains(c)) {
      // Inside: the triangle as it is (most of a tile's).
      std::array<uint32_t, 3> inside;
      for (int i = 0; i < 3; ++i) {
        inside[i] = add(PieceVertex{.p = patch.points[t[i]],
                                    .h = patch.heights[t[i]],
                                    .key = {VertexKey::kPatchVertex, t[i]}});
      }
      out.triangles.push_back(inside);
      continue;
    }
    const std::vector<PieceVertex> piece = clipper.Clip(t);
    if (piece.size() < 3) continue;
    std::vector<uint32_t> ring;
    for (const PieceVertex& v : piece) ring.push_back(add(v));
    for (size_t i = 1; i + 1 < ring.size(); ++i) {
      const std::array<uint32_t, 3> fan = {ring[0], ring[i], ring[i + 1]};
      if (Area2(out.points[fan[0]], out.points[fan[1]], out.points[fan[2]]) >
          0) {
        out.triangles.push_back(fan);
      }
    }
  }
  return out;
}

}  // namespace locator
