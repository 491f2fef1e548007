#include "server/tiles/quantized_mesh/quantized_mesh_tile.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/json_writer.h"
#include "common/status_macros.h"
#include "locator/mesh_patch.h"
#include "server/core/patch/clipped_mesh.h"
#include "server/core/patch/simplify_clipped_mesh.h"
#include "server/tiles/quantized_mesh/quantized_mesh_encoder.h"
#include "server/tiles/terrain_tile.h"

namespace locator {
namespace {

// Points along each side of a box mapped to the dataset's CRS.
constexpr int kSamplesPerSide = 16;
// How much a mapped box grows each way, as a fraction of its size, so
// that the bend of its sides between samples leaves no triangle out.
constexpr double kBoxMargin = 0.02;
// Metres per degree of latitude, and of longitude at the equator, for the
// spacing of the vertices.
constexpr double kMetresPerDegree = 111320;

BoundingBox Intersection(const BoundingBox& a, const BoundingBox& b) {
  return BoundingBox{std::max(a.min_x, b.min_x), std::max(a.min_y, b.min_y),
                     std::min(a.max_x, b.max_x), std::min(a.max_y, b.max_y)};
}

BoundingBox Grown(const BoundingBox& b, double fraction) {
  const double dx = fraction * b.width(), dy = fraction * b.height();
  return BoundingBox{b.min_x - dx, b.min_y - dy, b.max_x + dx, b.max_y + dy};
}

// The box in the dataset's CRS that holds `region` (degrees), from its
// outline mapped by `transformer`, or `dataset` (the dataset's own box)
// when part of the outline lies where PROJ does not map (outside the area
// of use of the dataset's CRS): the samples that do map could then miss
// the data between them.
BoundingBox RegionInDatasetCrs(const gis::CrsTransformer& transformer,
                               const BoundingBox& region,
                               const BoundingBox& dataset) {
  std::vector<Point2> outline;
  for (int i = 0; i <= kSamplesPerSide; ++i) {
    const double t = static_cast<double>(i) / kSamplesPerSide;
    const double x = region.min_x + t * region.width();
    const double y = region.min_y + t * region.height();
    outline.insert(outline.end(),
                   {Point2{x, region.min_y}, Point2{x, region.max_y},
                    Point2{region.min_x, y}, Point2{region.max_x, y}});
  }
  transformer.ToDatasetWhereDefined(outline);
  BoundingBox box;
  for (const Point2& p : outline) {
    if (!IsFinite(p)) return dataset;
    box.Extend(p);
  }
  return Grown(box, kBoxMargin);
}

// Drops the triangles of `patch` (in degrees) that its map from the
// dataset's CRS folded: those across the antimeridian, whose corners PROJ
// puts 360 degrees apart (clipped as they are they would span the world
// between), and those it turned over (round a pole) against the way it
// turns most (a CRS whose axes point west or south turns them all). A
// dataset across 180° keeps a seam there, a hole one triangle wide.
void DropFoldedTriangles(MeshPatch* patch) {
  const auto turn = [&](const std::array<uint32_t, 3>& t) {
    const Point2 &a = patch->points[t[0]], &b = patch->points[t[1]],
                 &c = patch->points[t[2]];
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  };
  int64_t balance = 0;
  for (const auto& t : patch->triangles) {
    const double d = turn(t);
    balance += d > 0 ? 1 : d < 0 ? -1 : 0;
  }
  const double way = balance >= 0 ? 1 : -1;
  std::erase_if(patch->triangles, [&](const std::array<uint32_t, 3>& t) {
    const double a = patch->points[t[0]].x, b = patch->points[t[1]].x,
                 c = patch->points[t[2]].x;
    return std::max({a, b, c}) - std::min({a, b, c}) > 180 ||
           !(way * turn(t) > 0);
  });
}

// Puts the vertices on `mesh`'s sides that are not the TIN's own on the
// TIN in the dataset's CRS, where its triangles are straight (in longitude
// and latitude they are only nearly: along a hull, a triangle a kilometre
// long is off by centimetres). A crossing of a TIN edge (`utm` holds the
// patch's points in the dataset's CRS) moves along the edge until it maps
// onto its side: Newton's method from the clip's point, with the slope of
// the edge in degrees, which PROJ's smooth map makes converge in a few
// steps; its height is the edge's there. A corner of the tile takes the
// TIN's height at its place, rounded to a micrometre, so that the tiles
// sharing it agree to the bit whichever triangle their locate lands in.
// The arithmetic depends only on the edge and the side, so the two tiles
// of a side compute the same points.
Status PutSidesOnTheTin(const Engine& engine,
                        const gis::CrsTransformer& transformer,
                        const MeshPatch& patch, std::span<const Point2> utm,
                        ClippedMesh* mesh) {
  constexpr int kNewtonSteps = 4;
  std::vector<uint32_t> crossings, corners;
  for (uint32_t v = 0; v < mesh->size(); ++v) {
    if (mesh->sides[v] == 0) continue;
    if (mesh->edges[v][0] != ClippedMesh::kNoEdge) {
      crossings.push_back(v);
    } else if (std::popcount(mesh->sides[v]) == 2) {
      corners.push_back(v);
    }
  }
  // Each crossing's parameter along its edge, from the edge's first end.
  std::vector<double> s(crossings.size());
  std::vector<Point2> at(crossings.size());
  const auto vertical = [&](uint32_t v) {
    return (mesh->sides[v] & (kWestSide | kEastSide)) != 0;
  };
  const auto coordinate = [](const Point2& p, bool x) { return x ? p.x : p.y; };
  for (size_t i = 0; i < crossings.size(); ++i) {
    const uint32_t v = crossings[i];
    const auto [a, b] = mesh->edges[v];
    const bool x = vertical(v);
    const double ca = coordinate(patch.points[a], x);
    s[i] = (coordinate(mesh->points[v], x) - ca) /
           (coordinate(patch.points[b], x) - ca);
  }
  for (int step = 0; step < kNewtonSteps && !crossings.empty(); ++step) {
    for (size_t i = 0; i < crossings.size(); ++i) {
      const auto [a, b] = mesh->edges[crossings[i]];
      at[i] = {utm[a].x + s[i] * (utm[b].x - utm[a].x),
               utm[a].y + s[i] * (utm[b].y - utm[a].y)};
    }
    RETURN_IF_ERROR(transformer.ToRequest(at));
    for (size_t i = 0; i < crossings.size(); ++i) {
      const uint32_t v = crossings[i];
      const auto [a, b] = mesh->edges[v];
      const bool x = vertical(v);
      const double line = coordinate(mesh->points[v], x);
      const double slope =
          coordinate(patch.points[b], x) - coordinate(patch.points[a], x);
      s[i] = std::clamp(s[i] - (coordinate(at[i], x) - line) / slope, 0.0, 1.0);
    }
  }
  for (size_t i = 0; i < crossings.size(); ++i) {
    const uint32_t v = crossings[i];
    const auto [a, b] = mesh->edges[v];
    // The side's coordinate stays exact; the other is where the edge is.
    if (vertical(v)) {
      mesh->points[v].y = at[i].y;
    } else {
      mesh->points[v].x = at[i].x;
    }
    mesh->heights[v] =
        patch.heights[a] + s[i] * (patch.heights[b] - patch.heights[a]);
  }

  std::vector<Point2> places;
  for (uint32_t v : corners) places.push_back(mesh->points[v]);
  if (places.empty()) return Status::OK();
  transformer.ToDatasetWhereDefined(places);
  std::vector<double> heights(places.size());
  RETURN_IF_ERROR(engine.RenderPoints(
      places, places.size(), Interpolation::kLinear,
      std::numeric_limits<double>::quiet_NaN(), heights.data()));
  constexpr double kMicrometres = 1e6;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (std::isnan(heights[i])) continue;  // keep the clip's
    mesh->heights[corners[i]] =
        std::round(heights[i] * kMicrometres) / kMicrometres;
  }
  return Status::OK();
}

}  // namespace

StatusOr<std::string> RenderQuantizedMesh(const Engine& engine,
                                          std::string_view name,
                                          const GeographicTile& tile) {
  RETURN_IF_ERROR(CheckTileSource(engine, name, kQuantizedMeshCrs));
  const BoundingBox tile_box = tile.Box();
  StatusOr<BoundingBox> data = DatasetBoxIn(engine, kQuantizedMeshCrs);
  if (!data.ok()) return data.status();
  const BoundingBox region = Intersection(tile_box, Grown(*data, kBoxMargin));
  ClippedMesh clipped;
  if (!region.empty()) {
    gis::CrsTransformer* transformer = nullptr;
    RETURN_IF_ERROR(gis::CrsTransformer::ForThread(
        std::string(kQuantizedMeshCrs), engine.dataset_info().crs,
        &transformer));
    const BoundingBox box = RegionInDatasetCrs(
        *transformer, region, engine.dataset_info().bounding_box);
    if (!box.empty()) {
      MeshPatch patch;
      RETURN_IF_ERROR(engine.MeshInBox(box, kMaxTileSourceVertices, &patch));
      const std::vector<Point2> utm = patch.points;
      RETURN_IF_ERROR(transformer->ToRequest(patch.points));
      DropFoldedTriangles(&patch);
      clipped = ClipMeshToBox(patch, tile_box);
      RETURN_IF_ERROR(
          PutSidesOnTheTin(engine, *transformer, patch, utm, &clipped));
    }
  }
  // Triangles are shaped on the ground: a degree of longitude is the
  // cosine of the latitude of a degree of latitude.
  const double middle = (tile_box.min_y + tile_box.max_y) / 2;
  const double x_scale = std::max(0.01, std::cos(middle * M_PI / 180));
  return EncodeQuantizedMesh(
      SimplifyClippedMesh(clipped, GeometricError(tile.z), x_scale), tile_box);
}

uint32_t DeepestQuantizedMeshLevel(const Engine& engine,
                                   const BoundingBox& lon_lat) {
  const double middle = (lon_lat.min_y + lon_lat.max_y) / 2;
  const double area = lon_lat.width() * lon_lat.height() * kMetresPerDegree *
                      kMetresPerDegree *
                      std::max(0.01, std::cos(middle * M_PI / 180));
  const double spacing =
      std::sqrt(area / std::max<uint64_t>(engine.dataset_info().vertices, 1));
  constexpr double kTileSpacings = 64;
  // A level-0 tile is 180 degrees wide.
  const double level =
      std::ceil(std::log2(180 * kMetresPerDegree / (kTileSpacings * spacing)));
  if (!(level > 0)) return 0;  // also NaN
  return static_cast<uint32_t>(
      std::min<double>(level, GeographicTile::kMaxLevel));
}

StatusOr<std::string> LayerJson(const Engine& engine, std::string_view name,
                                std::string_view version) {
  RETURN_IF_ERROR(CheckTileSource(engine, name, kQuantizedMeshCrs));
  StatusOr<BoundingBox> lon_lat = DatasetBoxIn(engine, kQuantizedMeshCrs);
  if (!lon_lat.ok()) return lon_lat.status();
  const BoundingBox b = Intersection(*lon_lat, BoundingBox{-180, -90, 180, 90});
  const uint32_t deepest = DeepestQuantizedMeshLevel(engine, b);
  JsonWriter out;
  out.BeginObject()
      .Key("tilejson")
      .String("2.1.0")
      .Key("name")
      .String(name)
      .Key("version")
      .String(version)
      .Key("format")
      .String("quantized-mesh-1.0")
      .Key("scheme")
      .String("tms")
      .Key("tiles")
      .BeginArray()
      .String("{z}/{x}/{y}.terrain?v={version}")
      .EndArray()
      .Key("projection")
      .String(kQuantizedMeshCrs)
      .Key("bounds")
      .BeginArray()
      .Number(b.min_x)
      .Number(b.min_y)
      .Number(b.max_x)
      .Number(b.max_y)
      .EndArray()
      .Key("minzoom")
      .Integer(0)
      .Key("maxzoom")
      .Integer(deepest)
      .Key("extensions")
      .BeginArray()
      .EndArray()
      .Key("available")
      .BeginArray();
  for (uint32_t z = 0; z <= deepest; ++z) {
    const double side = std::ldexp(180.0, -static_cast<int>(z));
    const auto tile_of = [&](double degrees, double origin, uint32_t count) {
      const double index = std::floor((degrees - origin) / side);
      return static_cast<uint32_t>(std::clamp<double>(index, 0, count - 1));
    };
    const uint32_t rows = uint32_t{1} << z;
    out.BeginArray()
        .BeginObject()
        .Key("startX")
        .Integer(tile_of(b.min_x, -180, 2 * rows))
        .Key("startY")
        .Integer(tile_of(b.min_y, -90, rows))
        .Key("endX")
        .Integer(tile_of(b.max_x, -180, 2 * rows))
        .Key("endY")
        .Integer(tile_of(b.max_y, -90, rows))
        .EndObject()
        .EndArray();
  }
  out.EndArray().EndObject();
  return out.TakeText();
}

}  // namespace locator
