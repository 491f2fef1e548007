// TinMesh: the triangulation greedy insertion refines. A half-edge mesh of
// counter-clockwise triangles in flat arrays, with constrained edges, that
// inserts one point at a time and restores the constrained Delaunay property
// by Lawson's flips (never across a constrained edge).
//
// Owns: the vertices' coordinates and a 32-byte record per triangle (three
// corners, three twins, a tag, and a stamp for touched()), one cache line
// for all a step reads of a triangle. Half-edge h = 3t + i runs from corner i
// to corner i + 1 of triangle t (indices mod 3); Twin(h) is the opposite
// half-edge of the neighbouring triangle, or kNoTwin on the mesh's boundary. An
// edge without a twin is always constrained; a constrained edge with a twin
// separates two triangles that flips must keep apart (a breakline, a domain
// boundary). The tag (e.g. in or out of a domain) is the caller's; the
// triangles an insertion makes from a triangle keep its tag.
//
// Invariants: every triangle is strictly counter-clockwise; twins are
// mutual and run opposite ways; a constrained edge's twin is constrained.
// Insertion keeps them, and keeps the mesh constrained Delaunay if it was
// (a flip is made only when the in-circle test asks for it and the two new
// triangles are strictly counter-clockwise, so a mesh that is not Delaunay
// stays a valid triangulation).
//
// Thread-safety: none; one thread builds one mesh.

#ifndef LOCATOR_CORE_TERRAIN_TIN_MESH_H_
#define LOCATOR_CORE_TERRAIN_TIN_MESH_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "locator/geometry.h"
#include "server/core/cgal/orientation.h"
#include "server/core/mesh/large_vector.h"

namespace locator {

class TinMesh {
 public:
  // What the vertices' coordinates are, which decides the predicates:
  // small integers (grid coordinates below 2^24: exact in 64- and 128-bit
  // integer arithmetic, no filter needed) or any doubles (CGAL's filtered
  // exact predicates).
  enum class Coordinates { kAnyDouble, kGridIntegers };

  explicit TinMesh(Coordinates coordinates = Coordinates::kAnyDouble)
      : integers_(coordinates == Coordinates::kGridIntegers) {}

  static constexpr uint32_t kNoTwin = 0x7fffffffu;
  static constexpr uint32_t kNone = 0xffffffffu;

  static uint32_t TriangleOf(uint32_t h) { return h / 3; }
  static uint32_t Next(uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static uint32_t Prev(uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }

  size_t num_vertices() const { return points_.size(); }
  size_t num_triangles() const { return records_.size(); }

  // Adds a vertex at p (not yet in any triangle); returns its index.
  uint32_t AddVertex(const Point2& p);
  const Point2& point(uint32_t v) const { return points_[v]; }

  // Adds the counter-clockwise triangle (a, b, c) without twins, tagged
  // `tag`; returns its index. For building a first mesh; Link() its edges.
  uint32_t AddTriangle(uint32_t a, uint32_t b, uint32_t c, uint8_t tag = 0);
  // Makes half-edges h and g twins (they must run opposite ways).
  void Link(uint32_t h, uint32_t g);
  // Marks the edge of half-edge h (and its twin) constrained.
  void Constrain(uint32_t h);

  uint32_t Corner(uint32_t t, int i) const { return records_[t].corner[i]; }
  // The vertex half-edge h starts at.
  uint32_t Origin(uint32_t h) const { return records_[h / 3].corner[h % 3]; }
  uint32_t Twin(uint32_t h) const { return RawTwin(h) & kTwinMask; }
  bool IsConstrained(uint32_t h) const { return RawTwin(h) & kConstrainedBit; }
  uint8_t tag(uint32_t t) const { return records_[t].tag; }
  void set_tag(uint32_t t, uint8_t tag) { records_[t].tag = tag; }

  // Inserts vertex v, which lies in the closed triangle t and is none of
  // its corners: t is split in three, or, with v on an edge, the two
  // triangles of that edge in two each (a constrained edge stays
  // constrained in its two halves); then edges are flipped until the mesh
  // is (constrained) Delaunay again. Afterwards touched() lists every
  // triangle that was created or rewritten, each once: together they cover
  // exactly the region the triangles of those indices covered before
  // (the new ones covered nothing). False, with nothing changed, if v is
  // outside t or one of its corners.
  bool Insert(uint32_t v, uint32_t t);
  const std::vector<uint32_t>& touched() const { return touched_; }

  // Renumbers vertices and triangles: new vertex k is old vertex
  // vertex_order[k], new triangle k old triangle triangle_order[k] (each a
  // permutation). Geometry and tags are unchanged; touched() is cleared.
  void Renumber(std::span<const uint32_t> vertex_order,
                std::span<const uint32_t> triangle_order);
  // Frees memory held beyond the current size.
  void ShrinkToFit();
  // Reserves room for `triangles` triangles and `vertices` vertices.
  void Reserve(size_t triangles, size_t vertices);
  // Bytes held by the arrays (capacity, not size).
  size_t MemoryBytes() const;

 private:
  static constexpr uint32_t kConstrainedBit = 0x80000000u;
  static constexpr uint32_t kTwinMask = 0x7fffffffu;

  // Writes triangle t as (a, b, c) with the given raw twin fields
  // (constrained bit included), linking each twin back; records t in
  // touched_.
  uint32_t SetTriangle(uint32_t t, uint32_t a, uint32_t b, uint32_t c,
                       std::array<uint32_t, 3> twins, uint8_t tag);
  // The twin field of h: its twin's index and the constrained bit. A new
  // half-edge given h's old field stays the edge h was.
  uint32_t RawTwin(uint32_t h) const { return records_[h / 3].twin[h % 3]; }
  uint32_t& RawTwin(uint32_t h) { return records_[h / 3].twin[h % 3]; }
  void InsertInTriangle(uint32_t v, uint32_t t);
  void InsertOnEdge(uint32_t v, uint32_t h);
  // Flips edges, starting at half-edge h whose triangle's third corner is
  // the new vertex, until each edge opposite it is locally Delaunay.
  void Legalize(uint32_t h);
  void Touch(uint32_t t);
  // The predicates, exact either way.
  Side Orient(uint32_t a, uint32_t b, uint32_t c) const;
  bool InCircle(uint32_t a, uint32_t b, uint32_t c, uint32_t d) const;

  bool integers_;
  struct Record {
    uint32_t corner[3];
    uint32_t twin[3];  // twin index | kConstrainedBit
    // touched_ holds the triangle iff stamp == stamp_.
    uint32_t stamp;
    uint8_t tag;
  };
  static_assert(sizeof(Record) == 32);

  LargeVector<Point2> points_;
  LargeVector<Record> records_;
  std::vector<uint32_t> touched_;
  uint32_t stamp_ = 0;
  std::vector<uint32_t> pending_;  // Legalize's stack of half-edges
};

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_TIN_MESH_H_
