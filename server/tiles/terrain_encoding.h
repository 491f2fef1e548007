// TerrainEncoding: how a terrain tile's pixel holds a height in its red,
// green and blue bytes, in the two encodings web maps decode (MapLibre's and
// Mapbox's raster-dem, deck.gl's TerrainLayer):
//
//   terrarium  height = R * 256 + G + B / 256 - 32768    (quantum 1/256 m)
//   mapbox     height = -10000 + (R * 65536 + G * 256 + B) * 0.1
//                                                         (quantum 0.1 m)
//
// A height is rounded to the nearest step of the encoding; one outside the
// encoding's range (terrarium: -32768 up to 32768 - 1/256, mapbox: -10000
// up to 1667721.5) is clamped to it, as no byte can say more.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_TILES_TERRAIN_ENCODING_H_
#define LOCATOR_SERVER_TILES_TERRAIN_ENCODING_H_

#include <array>
#include <cstdint>
#include <string_view>

#include "locator/status_or.h"

namespace locator {

enum class TerrainEncoding { kTerrarium, kMapbox };

// The encoding named `name` ("terrarium" or "mapbox"; empty: terrarium);
// InvalidArgument naming the supported ones otherwise.
StatusOr<TerrainEncoding> ParseTerrainEncoding(std::string_view name);

// "terrarium" or "mapbox", as TileJSON's `encoding` names them.
std::string_view TerrainEncodingName(TerrainEncoding encoding);

// The height step the encoding can tell apart, in metres.
double TerrainQuantum(TerrainEncoding encoding);

// The red, green and blue bytes of `height` (finite).
std::array<uint8_t, 3> EncodeHeight(TerrainEncoding encoding, double height);

// The height that red, green and blue bytes say.
double DecodeHeight(TerrainEncoding encoding,
                    const std::array<uint8_t, 3>& rgb);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_TERRAIN_ENCODING_H_
