#include "server/core/tiling/tile_triangulation.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <string>

#include "server/core/tiling/cells/circumdisk.h"

namespace locator {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

struct FaceState {
  // The face is a triangle (or hull edge) of the global triangulation.
  bool certified = false;
  // Its index among the tile's owned triangles, once they are numbered.
  uint32_t owned = TileTriangles::kOpen;
};

using VertexBase =
    CGAL::Triangulation_vertex_base_with_info_2<uint32_t, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<FaceState, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Face_handle = Delaunay::Face_handle;
using Vertex_handle = Delaunay::Vertex_handle;

Point2 PointOf(Vertex_handle v) { return {v->point().x(), v->point().y()}; }

// One tile's triangulation, from its first points to its owned triangles.
class TileBuild {
 public:
  TileBuild(const TileContext& context, const Tile& tile, HaloCells* halo)
      : c_(context),
        tile_(tile),
        halo_(*halo),
        is_pending_(tile.end_vertex - tile.first_vertex, false) {}

  Status Run(TileTriangles* out);

 private:
  bool Own(uint32_t index) const {
    return index >= tile_.first_vertex && index < tile_.end_vertex;
  }
  bool HasOwnVertex(Face_handle f) const {
    for (int i = 0; i < 3; ++i) {
      const Vertex_handle v = f->vertex(i);
      if (!dt_.is_infinite(v) && Own(v->info())) return true;
    }
    return false;
  }
  // Marks the own cells seen, sets the window one cell around them and
  // wants the ring of cells around each.
  std::vector<uint32_t> SeedOwnCells();
  void SetReach(uint32_t reach);
  void InsertCells(std::vector<uint32_t> cells);
  // Whether f is certified (checking it now if it was not), noting in
  // beyond_ whether the region it needs leaves the window.
  bool Certify(Face_handle f);
  // Round one: every face with an own vertex.
  void CheckAllFaces();
  // Later rounds: the stars of the pending own vertices.
  void CheckPending();
  void AddPending(Face_handle f);
  Status Fail(const std::string& what) const {
    return Status::Internal("tile of vertices " +
                            std::to_string(tile_.first_vertex) + ".." +
                            std::to_string(tile_.end_vertex) + ": " + what);
  }
  Status Emit(bool all_certified, TileTriangles* out);

  const TileContext& c_;
  const Tile tile_;
  HaloCells& halo_;
  Delaunay dt_;
  Face_handle hint_;
  HaloCells::Window own_box_{0, 0, 0, 0};
  uint32_t reach_ = 1;
  bool beyond_ = false;
  // Own vertices with a star not yet all certified.
  std::vector<Vertex_handle> pending_;
  std::vector<bool> is_pending_;  // by own index
  std::vector<TileVertex> buffer_;
  size_t inserted_ = 0;
};

std::vector<uint32_t> TileBuild::SeedOwnCells() {
  std::vector<uint32_t> own;
  const uint32_t last = c_.grid.side() - 1;
  own_box_ = {last, last, 0, 0};
  for (uint32_t cell = tile_.first_cell; cell < tile_.end_cell; ++cell) {
    if (c_.source.CellSize(cell) == 0) continue;
    own.push_back(cell);
    uint32_t column, row;
    c_.grid.CellPosition(cell, &column, &row);
    halo_.MarkSeen(column, row);
    own_box_.min_column = std::min(own_box_.min_column, column);
    own_box_.min_row = std::min(own_box_.min_row, row);
    own_box_.max_column = std::max(own_box_.max_column, column);
    own_box_.max_row = std::max(own_box_.max_row, row);
  }
  SetReach(1);
  // The first halo: the cells around each own cell, so that own vertices
  // are rarely on the hull of what the tile sees.
  for (const uint32_t cell : own) {
    uint32_t column, row;
    c_.grid.CellPosition(cell, &column, &row);
    (void)halo_.CoverBox({column == 0 ? 0 : column - 1, row == 0 ? 0 : row - 1,
                          std::min(column + 1, last), std::min(row + 1, last)});
  }
  return own;
}

void TileBuild::SetReach(uint32_t reach) {
  reach_ = reach;
  const uint32_t last = c_.grid.side() - 1;
  const auto grow_down = [&](uint32_t v) { return v > reach ? v - reach : 0; };
  const auto grow_up = [&](uint32_t v) {
    return last - v > reach ? v + reach : last;
  };
  halo_.SetWindow({grow_down(own_box_.min_column), grow_down(own_box_.min_row),
                   grow_up(own_box_.max_column), grow_up(own_box_.max_row)});
}

void TileBuild::InsertCells(std::vector<uint32_t> cells) {
  // Along the curve, each point near the one before (the insertion's hint).
  std::sort(cells.begin(), cells.end());
  buffer_.clear();
  for (const uint32_t cell : cells) c_.source.ReadCell(cell, &buffer_);
  for (const TileVertex& v : buffer_) {
    const Vertex_handle h =
        dt_.insert(Kernel::Point_2(v.point.x, v.point.y), hint_);
    h->info() = v.index;
    hint_ = h->face();
  }
  inserted_ += buffer_.size();
}

bool TileBuild::Certify(Face_handle f) {
  if (f->info().certified) return true;
  HaloCells::Cover cover;
  if (dt_.is_infinite(f)) {
    // The tile's points are left of p -> q; the outside is right of it.
    const int i = f->index(dt_.infinite_vertex());
    const Vertex_handle p = f->vertex(Delaunay::cw(i));
    const Vertex_handle q = f->vertex(Delaunay::ccw(i));
    if (!c_.hull.Contains(p->info(), q->info())) {
      cover = halo_.CoverRightOf(PointOf(p), PointOf(q));
    }
  } else {
    Disk disk;
    cover = CircumdiskBound(PointOf(f->vertex(0)), PointOf(f->vertex(1)),
                            PointOf(f->vertex(2)), &disk)
                ? halo_.CoverDisk(disk)
                : halo_.CoverWindow();
  }
  beyond_ |= cover.beyond;
  f->info().certified = cover.covered;
  return cover.covered;
}

void TileBuild::AddPending(Face_handle f) {
  for (int i = 0; i < 3; ++i) {
    const Vertex_handle v = f->vertex(i);
    if (dt_.is_infinite(v) || !Own(v->info())) continue;
    const uint32_t k = v->info() - tile_.first_vertex;
    if (is_pending_[k]) continue;
    is_pending_[k] = true;
    pending_.push_back(v);
  }
}

void TileBuild::CheckAllFaces() {
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    if (HasOwnVertex(f) && !Certify(f)) AddPending(f);
  }
}

void TileBuild::CheckPending() {
  std::vector<Vertex_handle> still;
  for (const Vertex_handle v : pending_) {
    bool certified = true;
    auto f = dt_.incident_faces(v);
    const auto end = f;
    do {
      certified &= Certify(f);
    } while (++f != end);
    if (certified) {
      is_pending_[v->info() - tile_.first_vertex] = false;
    } else {
      still.push_back(v);
    }
  }
  pending_.swap(still);
}

Status TileBuild::Emit(bool all_certified, TileTriangles* out) {
  std::vector<Face_handle> owned;
  owned.reserve(2 * (tile_.end_vertex - tile_.first_vertex) + 2);
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    const uint32_t smallest = std::min(
        {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    if (!Own(smallest)) continue;
    if (!all_certified && !f->info().certified) {
      return Fail("owned triangle of vertices " +
                  std::to_string(f->vertex(0)->info()) + ", " +
                  std::to_string(f->vertex(1)->info()) + ", " +
                  std::to_string(f->vertex(2)->info()) + " is not certified");
    }
    f->info().owned = static_cast<uint32_t>(owned.size());
    owned.push_back(f);
  }
  out->triangles.reserve(owned.size());
  for (const Face_handle f : owned) {
    MeshTriangle m;
    for (int i = 0; i < 3; ++i) {
      m.corner[i] = f->vertex(i)->info();
      const Face_handle n = f->neighbor(i);
      m.neighbor[i] =
          dt_.is_infinite(n) ? TileTriangles::kOpen : n->info().owned;
    }
    out->triangles.push_back(m);
  }
  out->own_points = tile_.end_vertex - tile_.first_vertex;
  out->halo_points = inserted_ - out->own_points;
  return Status::OK();
}

Status TileBuild::Run(TileTriangles* out) {
  halo_.Clear();
  out->rounds = 0;
  InsertCells(SeedOwnCells());
  if (tile_.first_vertex == 0 && tile_.end_vertex == c_.vertices) {
    // One tile: it sees every point, so everything is final.
    return Emit(/*all_certified=*/true, out);
  }
  InsertCells(halo_.TakeWanted());
  bool checked_all = false;
  for (;;) {
    ++out->rounds;
    beyond_ = false;
    if (dt_.dimension() < 2) {
      beyond_ = halo_.CoverWindow().beyond;  // all collinear: see more
    } else if (!checked_all) {
      CheckAllFaces();
      checked_all = true;
    } else {
      CheckPending();
    }
    if (checked_all && pending_.empty()) break;
    std::vector<uint32_t> wanted = halo_.TakeWanted();
    if (wanted.empty() && !beyond_) {
      return Fail(dt_.dimension() < 2
                      ? "all points are collinear"
                      : "a hull edge of all the points is not on their hull");
    }
    InsertCells(std::move(wanted));
    if (beyond_) SetReach(2 * reach_);
  }
  return Emit(/*all_certified=*/false, out);
}

}  // namespace

std::vector<Tile> CutTiles(const CellGrid& grid, const CellSource& source,
                           size_t tile_vertices) {
  std::vector<Tile> tiles;
  Tile tile;
  const auto cells = static_cast<uint32_t>(grid.num_cells());
  for (uint32_t cell = 0; cell < cells; ++cell) {
    tile.end_vertex += source.CellSize(cell);
    tile.end_cell = cell + 1;
    if (tile.end_vertex - tile.first_vertex >= tile_vertices) {
      tiles.push_back(tile);
      tile = Tile{cell + 1, cell + 1, tile.end_vertex, tile.end_vertex};
    }
  }
  if (tile.end_vertex > tile.first_vertex) tiles.push_back(tile);
  return tiles;
}

Status TriangulateTile(const TileContext& context, const Tile& tile,
                       HaloCells* halo, TileTriangles* out) {
  return TileBuild(context, tile, halo).Run(out);
}

}  // namespace locator
