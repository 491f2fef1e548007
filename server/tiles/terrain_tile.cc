#include "server/tiles/terrain_tile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/input_text.h"
#include "common/json_writer.h"
#include "common/status_macros.h"
#include "server/tiles/png_image.h"

namespace locator {
namespace {

// Points along each side of the dataset's box mapped to another CRS: a box
// of a projected CRS bends in lon/lat, so its corners alone could miss the
// extremes.
constexpr int kBoxSamplesPerSide = 16;
// Web Mercator's latitude limit, where the tile square ends.
constexpr double kMaxLatitude = 85.0511287798066;

// The approximate transform of a row of pixel centres, as GDAL's
// GDALApproxTransform: the row's two ends and its middle are transformed
// exactly; where the linear interpolation of the ends is within
// `tolerance` (dataset units, in x and in y) of the exact middle, the
// pixels between are interpolated, otherwise the span is split at the
// middle and each half is treated alike. PROJ's map from Web Mercator to a
// dataset's CRS is smooth, so over a span short enough to pass the test it
// is close to a quadratic, whose distance from its chord peaks at the
// middle: the middle's error bounds the span's. A span with a point PROJ
// cannot map is transformed exactly, point by point.
class RowTransform {
 public:
  RowTransform(const gis::CrsTransformer& transformer, double tolerance)
      : transformer_(transformer), tolerance_(tolerance) {}

  // Maps row[first..last] in place; row[first] and row[last] are mapped
  // already, the others are still in the request CRS.
  void Span(std::span<Point2> row, size_t first, size_t last) const {
    if (last - first < 2) return;
    const size_t middle = first + (last - first) / 2;
    const Point2 a = row[first], b = row[last];
    Exact(row.subspan(middle, 1));
    const Point2 m = row[middle];
    if (!IsFinite(a) || !IsFinite(b) || !IsFinite(m)) {
      Exact(row.subspan(first + 1, middle - first - 1));
      Exact(row.subspan(middle + 1, last - middle - 1));
      return;
    }
    const Point2 chord = At(a, b, first, last, middle);
    if (std::abs(chord.x - m.x) > tolerance_ ||
        std::abs(chord.y - m.y) > tolerance_) {
      Span(row, first, middle);
      Span(row, middle, last);
      return;
    }
    for (size_t i = first + 1; i < last; ++i) {
      if (i != middle) row[i] = At(a, b, first, last, i);
    }
  }

  void Exact(std::span<Point2> points) const {
    transformer_.ToDatasetWhereDefined(points, /*known_inside=*/true);
  }

 private:
  // The point of index i on the chord from a (index first) to b (last).
  static Point2 At(const Point2& a, const Point2& b, size_t first, size_t last,
                   size_t i) {
    const double t = static_cast<double>(i - first) / (last - first);
    return Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  }

  const gis::CrsTransformer& transformer_;
  const double tolerance_;
};

}  // namespace

StatusOr<BoundingBox> DatasetBoxIn(const Engine& engine, std::string_view crs) {
  const BoundingBox& b = engine.dataset_info().bounding_box;
  std::vector<Point2> outline;
  for (int i = 0; i <= kBoxSamplesPerSide; ++i) {
    const double t = static_cast<double>(i) / kBoxSamplesPerSide;
    const double x = b.min_x + t * (b.max_x - b.min_x);
    const double y = b.min_y + t * (b.max_y - b.min_y);
    outline.insert(outline.end(), {Point2{x, b.min_y}, Point2{x, b.max_y},
                                   Point2{b.min_x, y}, Point2{b.max_x, y}});
  }
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(gis::CrsTransformer::ForThread(
      std::string(crs), engine.dataset_info().crs, &transformer));
  RETURN_IF_ERROR(transformer->ToRequest(outline));
  constexpr double kInf = std::numeric_limits<double>::infinity();
  BoundingBox box{kInf, kInf, -kInf, -kInf};
  for (const Point2& p : outline) {
    box.min_x = std::min(box.min_x, p.x);
    box.min_y = std::min(box.min_y, p.y);
    box.max_x = std::max(box.max_x, p.x);
    box.max_y = std::max(box.max_y, p.y);
  }
  return box;
}

Status CheckTileSource(const Engine& engine, std::string_view name,
                       std::string_view tile_crs) {
  if (engine.dataset_info().crs.empty()) {
    return Status::FailedPrecondition(
        "dataset " + QuotedInput(name) +
        " has no CRS, so its terrain has no place on a web map's tiles (" +
        std::string(tile_crs) +
        "); load it from a source that has one, or give it one");
  }
  if (!engine.dataset_info().has_values) {
    return Status::FailedPrecondition("dataset " + QuotedInput(name) +
                                      " has no values to draw as terrain");
  }
  return Status::OK();
}

Status TilePixelsInDatasetCrs(const Engine& engine, const TileAddress& tile,
                              std::vector<Point2>* pixels) {
  const RasterSpec raster = tile.Raster();
  // A centre's x depends on its column alone and its y on its row alone.
  std::vector<double> column_x(raster.width);
  for (uint32_t col = 0; col < raster.width; ++col) {
    column_x[col] = raster.CellCentre(col, 0).x;
  }
  pixels->resize(raster.cells());
  Point2* pixel = pixels->data();
  for (uint32_t row = 0; row < raster.height; ++row) {
    const double y = raster.CellCentre(0, row).y;
    for (uint32_t col = 0; col < raster.width; ++col) {
      *pixel++ = Point2{column_x[col], y};
    }
  }
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(gis::CrsTransformer::ForThread(
      std::string(kTileCrs), engine.dataset_info().crs, &transformer));
  // Web Mercator's longitude depends on x alone and its latitude on y
  // alone, so a tile inside the area of use needs no check per pixel; a
  // tile reaching outside is transformed exactly, pixel by pixel, with it.
  if (!transformer->SeparableBoxInAreaOfUse(tile.Box())) {
    transformer->ToDatasetWhereDefined(*pixels);
    return Status::OK();
  }
  const size_t last = raster.width - 1;
  for (uint32_t row = 0; row < raster.height; ++row) {
    const std::span<Point2> line(pixels->data() + size_t{row} * raster.width,
                                 raster.width);
    transformer->ToDatasetWhereDefined(line.first(1), /*known_inside=*/true);
    transformer->ToDatasetWhereDefined(line.last(1), /*known_inside=*/true);
    // The bound: kTilePositionTolerance of the row's pixel width in the
    // dataset's CRS (NaN if an end is undefined: then no span passes).
    const double pixel =
        std::hypot(line[last].x - line[0].x, line[last].y - line[0].y) / last;
    RowTransform(*transformer, kTilePositionTolerance * pixel)
        .Span(line, 0, last);
  }
  return Status::OK();
}

StatusOr<std::string> RenderTerrainTile(const Engine& engine,
                                        std::string_view name,
                                        const TileAddress& tile,
                                        TerrainEncoding encoding) {
  RETURN_IF_ERROR(CheckTileSource(engine, name));
  std::vector<Point2> pixels;
  RETURN_IF_ERROR(TilePixelsInDatasetCrs(engine, tile, &pixels));
  std::vector<double> heights(pixels.size());
  RETURN_IF_ERROR(engine.RenderPoints(
      pixels, TileAddress::kPixels, Interpolation::kLinear,
      std::numeric_limits<double>::quiet_NaN(), heights.data()));
  std::vector<uint8_t> rgba(heights.size() * 4);
  for (size_t i = 0; i < heights.size(); ++i) {
    // NaN is the nodata: outside the hull, the domain or the CRS's area.
    if (std::isnan(heights[i])) continue;  // stays transparent black
    const std::array<uint8_t, 3> rgb = EncodeHeight(encoding, heights[i]);
    std::copy(rgb.begin(), rgb.end(), rgba.begin() + 4 * i);
    rgba[4 * i + 3] = 255;
  }
  return EncodePng(rgba, TileAddress::kPixels, TileAddress::kPixels,
                   PngColor::kRgba);
}

StatusOr<std::string> TileJson(const Engine& engine, std::string_view name,
                               std::string_view tiles_url,
                               TerrainEncoding encoding) {
  RETURN_IF_ERROR(CheckTileSource(engine, name));
  StatusOr<BoundingBox> lon_lat = DatasetBoxIn(engine, "EPSG:4326");
  if (!lon_lat.ok()) return lon_lat.status();
  StatusOr<BoundingBox> mercator = DatasetBoxIn(engine, kTileCrs);
  if (!mercator.ok()) return mercator.status();
  const BoundingBox& b = *lon_lat;
  const double south = std::max(b.min_y, -kMaxLatitude);
  const double north = std::min(b.max_y, kMaxLatitude);
  const BoundingBox& m = *mercator;
  const double extent = std::max(m.max_x - m.min_x, m.max_y - m.min_y);
  const double area = (m.max_x - m.min_x) * (m.max_y - m.min_y);
  const double spacing =
      std::sqrt(area / std::max<uint64_t>(engine.dataset_info().vertices, 1));
  const uint32_t maxzoom = ZoomForPixelSize(spacing, /*round_up=*/true);
  const uint32_t minzoom = std::min(
      maxzoom,
      ZoomForPixelSize(extent / TileAddress::kPixels, /*round_up=*/false));
  JsonWriter out;
  out.BeginObject()
      .Key("tilejson")
      .String("3.0.0")
      .Key("name")
      .String(name)
      .Key("tiles")
      .BeginArray()
      .String(tiles_url)
      .EndArray()
      .Key("scheme")
      .String("xyz")
      .Key("minzoom")
      .Integer(minzoom)
      .Key("maxzoom")
      .Integer(maxzoom)
      .Key("bounds")
      .BeginArray()
      .Number(b.min_x)
      .Number(south)
      .Number(b.max_x)
      .Number(north)
      .EndArray()
      .Key("center")
      .BeginArray()
      .Number((b.min_x + b.max_x) / 2)
      .Number((south + north) / 2)
      .Integer(minzoom)
      .EndArray()
      .Key("encoding")
      .String(TerrainEncodingName(encoding))
      .Key("tileSize")
      .Integer(TileAddress::kPixels)
      .EndObject();
  return out.TakeText();
}

std::string TileETag(uint64_t generation, std::string_view variant) {
  static const uint64_t run = [] {
    std::random_device random;
    return uint64_t{random()} << 32 | random();
  }();
  char text[64];
  std::snprintf(text, sizeof text, "\"%016llx-%llu-",
                static_cast<unsigned long long>(run),
                static_cast<unsigned long long>(generation));
  return text + std::string(variant) + "\"";
}

}  // namespace locator
