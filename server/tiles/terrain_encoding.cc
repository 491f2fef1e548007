#include "server/tiles/terrain_encoding.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/input_text.h"

namespace locator {
namespace {

// Heights are written as a count of quanta above the encoding's lowest
// height, in 24 bits.
constexpr double kMaxSteps = (1 << 24) - 1;

double Lowest(TerrainEncoding encoding) {
  return encoding == TerrainEncoding::kTerrarium ? -32768.0 : -10000.0;
}

}  // namespace

StatusOr<TerrainEncoding> ParseTerrainEncoding(std::string_view name) {
  if (name.empty() || name == "terrarium") return TerrainEncoding::kTerrarium;
  if (name == "mapbox") return TerrainEncoding::kMapbox;
  return Status::InvalidArgument("unknown encoding " + QuotedInput(name) +
                                 "; the encodings are terrarium (the "
                                 "default) and mapbox (Terrain-RGB)");
}

std::string_view TerrainEncodingName(TerrainEncoding encoding) {
  return encoding == TerrainEncoding::kTerrarium ? "terrarium" : "mapbox";
}

double TerrainQuantum(TerrainEncoding encoding) {
  return encoding == TerrainEncoding::kTerrarium ? 1.0 / 256 : 0.1;
}

std::array<uint8_t, 3> EncodeHeight(TerrainEncoding encoding, double height) {
  // Rounded to the nearest step (ties to even, as nearbyint) by adding and
  // taking away 2^52, where a double's last bit is 1: a tile rounds every
  // pixel, and nearbyint is a library call. Clamping first keeps the sum
  // exact and gives what rounding first does, since the bounds are whole.
  const double clamped = std::clamp(
      (height - Lowest(encoding)) / TerrainQuantum(encoding), 0.0, kMaxSteps);
  const double steps = (clamped + 0x1p52) - 0x1p52;
  const auto n = static_cast<uint32_t>(steps);
  return {static_cast<uint8_t>(n >> 16), static_cast<uint8_t>(n >> 8),
          static_cast<uint8_t>(n)};
}

double DecodeHeight(TerrainEncoding encoding,
                    const std::array<uint8_t, 3>& rgb) {
  const uint32_t n = uint32_t{rgb[0]} << 16 | uint32_t{rgb[1]} << 8 | rgb[2];
  return Lowest(encoding) + n * TerrainQuantum(encoding);
}

}  // namespace locator
