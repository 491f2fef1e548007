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

// The approximate transform of a tile's pixel centres, GDAL's approximate
// transformer (GDALApproxTransform, along a line) taken to two dimensions.
// A block's four corners are transformed exactly, and so are its centre
// and the middles of its sides; where the bilinear interpolation of the
// corners is within `tolerance` (dataset units, in x and in y) of those
// five, the block's other pixels are interpolated, otherwise it is split
// into four and each quarter is treated alike. PROJ's map from Web
// Mercator to a dataset's CRS is smooth, so over a block small enough to
// pass it is close to a quadratic, whose distance from the bilinear
// interpolant peaks at the middles checked. A block with a point PROJ
// cannot map is transformed exactly, point by point.
class BlockTransform {
 public:
  // Will map the centres of columns `column_x` by rows `row_y` (two or more
  // of each) into `pixels`, row by row: see Run().
  BlockTransform(const gis::CrsTransformer& transformer,
                 std::span<const double> column_x,
                 std::span<const double> row_y, std::span<Point2> pixels)
      : transformer_(transformer),
        column_x_(column_x),
        row_y_(row_y),
        pixels_(pixels),
        exact_(pixels.size(), 0) {}

  // Maps the tile's four corners exactly; then its pixels are one pixel of
  // the shorter of its top and bottom rows times `pixel_tolerance` apart
  // from their exact transforms at most.
  void Run(double pixel_tolerance) {
    const size_t last_column = column_x_.size() - 1;
    const size_t last_row = row_y_.size() - 1;
    for (size_t row : {size_t{0}, last_row}) {
      for (size_t col : {size_t{0}, last_column}) Exact(col, row);
    }
    const auto row_pixel = [&](size_t row) {
      const Point2& a = At(0, row);
      const Point2& b = At(last_column, row);
      return std::hypot(b.x - a.x, b.y - a.y) /
             static_cast<double>(last_column);
    };
    // NaN if a corner is undefined: then no block passes.
    tolerance_ = pixel_tolerance * std::min(row_pixel(0), row_pixel(last_row));
    Block(0, 0, last_column, last_row);
  }

 private:
  Point2& At(size_t col, size_t row) {
    return pixels_[row * column_x_.size() + col];
  }

  void Exact(size_t col, size_t row) {
    const size_t i = row * column_x_.size() + col;
    if (exact_[i]) return;
    pixels_[i] = Point2{column_x_[col], row_y_[row]};
    transformer_.ToDatasetWhereDefined(pixels_.subspan(i, 1),
                                       /*known_inside=*/true);
    exact_[i] = 1;
  }

  // Maps block [c0, c1] x [r0, r1], whose corners are mapped exactly.
  void Block(size_t c0, size_t r0, size_t c1, size_t r1) {
    if (c1 - c0 < 2 && r1 - r0 < 2) return;  // corners only
    const size_t cm = c0 + (c1 - c0) / 2;
    const size_t rm = r0 + (r1 - r0) / 2;
    const std::array<std::array<size_t, 2>, 5> checks = {
        {{cm, r0}, {cm, r1}, {c0, rm}, {c1, rm}, {cm, rm}}};
    bool passes = true;
    for (const auto& [col, row] : checks) {
      Exact(col, row);
      const Point2 exact = At(col, row);
      const Point2 guess = Bilinear(c0, r0, c1, r1, col, row);
      passes = passes && IsFinite(exact) && IsFinite(guess) &&
               std::abs(guess.x - exact.x) <= tolerance_ &&
               std::abs(guess.y - exact.y) <= tolerance_;
    }
    if (passes) {
      Fill(c0, r0, c1, r1);
      return;
    }
    // Halves only a side at least two pixels long.
    const std::array<size_t, 3> cols = {c0, c1 - c0 < 2 ? c1 : cm, c1};
    const std::array<size_t, 3> rows = {r0, r1 - r0 < 2 ? r1 : rm, r1};
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        if (cols[j] == cols[j + 1] || rows[i] == rows[i + 1]) continue;
        Block(cols[j], rows[i], cols[j + 1], rows[i + 1]);
      }
    }
  }

  // The bilinear interpolation at (col, row) of the corners of block
  // [c0, c1] x [r0, r1] (c0 < c1, r0 < r1).
  Point2 Bilinear(size_t c0, size_t r0, size_t c1, size_t r1, size_t col,
                  size_t row) {
    const double u = static_cast<double>(col - c0) / (c1 - c0);
    const double v = static_cast<double>(row - r0) / (r1 - r0);
    const Point2 left = Lerp(At(c0, r0), At(c0, r1), v);
    return Lerp(left, Lerp(At(c1, r0), At(c1, r1), v), u);
  }

  // Sets the pixels of block [c0, c1] x [r0, r1] not mapped exactly to
  // Bilinear(), row by row.
  void Fill(size_t c0, size_t r0, size_t c1, size_t r1) {
    const double width = static_cast<double>(c1 - c0);
    for (size_t row = r0; row <= r1; ++row) {
      const Point2 left = Bilinear(c0, r0, c1, r1, c0, row);
      const Point2 right = Bilinear(c0, r0, c1, r1, c1, row);
      const size_t first = row * column_x_.size();
      for (size_t col = c0; col <= c1; ++col) {
        if (exact_[first + col]) continue;
        pixels_[first + col] =
            Lerp(left, right, static_cast<double>(col - c0) / width);
      }
    }
  }

  static Point2 Lerp(const Point2& a, const Point2& b, double t) {
    return Point2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  }

  const gis::CrsTransformer& transformer_;
  const std::span<const double> column_x_;
  const std::span<const double> row_y_;
  const std::span<Point2> pixels_;
  std::vector<char> exact_;  // whether pixel i is mapped exactly
  double tolerance_ = 0;
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
  std::vector<double> column_x(raster.width), row_y(raster.height);
  for (uint32_t col = 0; col < raster.width; ++col) {
    column_x[col] = raster.CellCentre(col, 0).x;
  }
  for (uint32_t row = 0; row < raster.height; ++row) {
    row_y[row] = raster.CellCentre(0, row).y;
  }
  pixels->resize(raster.cells());
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(gis::CrsTransformer::ForThread(
      std::string(kTileCrs), engine.dataset_info().crs, &transformer));
  // Web Mercator's longitude depends on x alone and its latitude on y
  // alone, so a tile inside the area of use needs no check per pixel; a
  // tile reaching outside is transformed exactly, pixel by pixel, with it.
  if (!transformer->SeparableBoxInAreaOfUse(tile.Box())) {
    Point2* pixel = pixels->data();
    for (const double y : row_y) {
      for (const double x : column_x) *pixel++ = Point2{x, y};
    }
    transformer->ToDatasetWhereDefined(*pixels);
    return Status::OK();
  }
  BlockTransform(*transformer, column_x, row_y, *pixels)
      .Run(kTilePositionTolerance);
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
  // NaN is the nodata: outside the hull, the domain or the CRS's area.
  const auto nodata = [](double h) { return std::isnan(h); };
  const PngColor color = std::any_of(heights.begin(), heights.end(), nodata)
                             ? PngColor::kRgba
                             : PngColor::kRgb;
  const size_t pixel_bytes = BytesPerPixel(color);
  std::vector<uint8_t> image(heights.size() * pixel_bytes);
  for (size_t i = 0; i < heights.size(); ++i) {
    if (nodata(heights[i])) continue;  // stays transparent black
    const std::array<uint8_t, 3> rgb = EncodeHeight(encoding, heights[i]);
    uint8_t* pixel = image.data() + pixel_bytes * i;
    std::copy(rgb.begin(), rgb.end(), pixel);
    if (color == PngColor::kRgba) pixel[3] = 255;
  }
  return EncodePng(image, TileAddress::kPixels, TileAddress::kPixels, color);
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
