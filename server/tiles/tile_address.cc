#include "server/tiles/tile_address.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "common/input_text.h"

namespace locator {
namespace {

// The number in `text` if it is 1..9 decimal digits, else nullopt: no
// sign, no spaces, no leading "+", nothing after the digits.
std::optional<uint64_t> Digits(std::string_view text) {
  if (text.empty() || text.size() > 9) return std::nullopt;
  uint64_t value = 0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    return std::nullopt;
  }
  return value;
}

Status OutOfRange(std::string_view name, std::string_view text, uint64_t last) {
  return Status::InvalidArgument(
      "tile " + std::string(name) + " " + QuotedInput(text) +
      " is not a whole number in 0.." + std::to_string(last));
}

}  // namespace

BoundingBox TileAddress::Box() const {
  const double side = 2 * kHalfWorld / std::ldexp(1.0, static_cast<int>(z));
  return BoundingBox{-kHalfWorld + x * side, kHalfWorld - (y + 1) * side,
                     -kHalfWorld + (x + 1) * side, kHalfWorld - y * side};
}

RasterSpec TileAddress::Raster() const {
  return RasterSpec{.box = Box(), .width = kPixels, .height = kPixels};
}

StatusOr<TileAddress> ParseTileAddress(std::string_view z, std::string_view x,
                                       std::string_view y) {
  return ParseTilePath(z, x, y, TileAddress::kMaxZoom,
                       /*columns_at_zoom_0=*/1);
}

StatusOr<TileAddress> ParseTilePath(std::string_view z, std::string_view x,
                                    std::string_view y, uint32_t max_zoom,
                                    uint32_t columns_at_zoom_0) {
  const std::optional<uint64_t> zoom = Digits(z);
  if (!zoom.has_value() || *zoom > max_zoom) {
    return OutOfRange("zoom", z, max_zoom);
  }
  const uint64_t last_row = (uint64_t{1} << *zoom) - 1;
  const uint64_t last_column = columns_at_zoom_0 * (last_row + 1) - 1;
  const std::optional<uint64_t> column = Digits(x);
  if (!column.has_value() || *column > last_column) {
    return OutOfRange("x at zoom " + std::to_string(*zoom), x, last_column);
  }
  const std::optional<uint64_t> row = Digits(y);
  if (!row.has_value() || *row > last_row) {
    return OutOfRange("y at zoom " + std::to_string(*zoom), y, last_row);
  }
  return TileAddress{.z = static_cast<uint32_t>(*zoom),
                     .x = static_cast<uint32_t>(*column),
                     .y = static_cast<uint32_t>(*row)};
}

uint32_t ZoomForPixelSize(double metres, bool round_up) {
  const double zoom0 = 2 * TileAddress::kHalfWorld / TileAddress::kPixels;
  if (!(metres < zoom0)) return 0;  // also NaN
  const double exact = std::log2(zoom0 / metres);
  const double zoom = round_up ? std::ceil(exact) : std::floor(exact);
  return zoom >= TileAddress::kMaxZoom ? TileAddress::kMaxZoom
                                       : static_cast<uint32_t>(zoom);
}

}  // namespace locator
