// Hillshade tiles: the shaded relief of a dataset as XYZ Web-Mercator
// tiles (TileAddress), for a map to lay under or over its other layers.
//
// Each pixel is lit as `gdaldem hillshade` lights a raster cell, with its
// meanings of azimuth, altitude, z factor and scale, but the slope is the
// exact gradient of the TIN's facet under the pixel centre
// (Engine::RenderGradients) rather than Horn's estimate from a 3 x 3
// window of cells: where such a window lies on one facet the two agree
// (tests/server/tiles/hillshade_test.cc runs gdaldem to check it). The
// gradient is taken in the dataset's CRS, so the azimuth is measured from
// that CRS's grid north (for UTM, within its meridian convergence of true
// north, a degree or two). Pixels are grey (1 = darkest, 255 = lit
// head-on, as gdaldem's Byte output) and opaque where the TIN has a facet,
// transparent where it has none.
//
// Thread-safety: free functions over a thread-safe Engine; any thread.

#ifndef LOCATOR_SERVER_TILES_HILLSHADE_H_
#define LOCATOR_SERVER_TILES_HILLSHADE_H_

#include <cstdint>
#include <string>
#include <string_view>

#include "locator/engine.h"
#include "locator/raster.h"
#include "locator/status_or.h"
#include "server/tiles/tile_address.h"

namespace locator {

// The light and the relief's exaggeration, as gdaldem hillshade's -az,
// -alt, -z and -s.
struct HillshadeOptions {
  // Where the light comes from, in degrees clockwise from (grid) north.
  double azimuth = 315;
  // The light's height above the horizon, in degrees: 90 is straight above.
  double altitude = 45;
  // Vertical exaggeration.
  double z_factor = 1;
  // Horizontal units per vertical unit: 1 when both are metres, 111120 for
  // a dataset in degrees with heights in metres.
  double scale = 1;
};

// The options spelled by the query parameters `azimuth`, `altitude`,
// `z_factor` and `scale` (each "" for its default). InvalidArgument naming
// the parameter and its range unless: azimuth is a number from 0 to 360,
// altitude from 0 to 90, z_factor and scale positive and at most 1e9.
StatusOr<HillshadeOptions> ParseHillshadeOptions(std::string_view azimuth,
                                                 std::string_view altitude,
                                                 std::string_view z_factor,
                                                 std::string_view scale);

// The options as a short word for an ETag: "hillshade-AZ-ALT-Z-S" with
// every number exact (shortest round trip).
std::string HillshadeVariant(const HillshadeOptions& options);

// A light (HillshadeOptions) with its angles' sines and cosines worked out
// once, for the many facets of a tile. Immutable: safe to share.
class HillshadeLight {
 public:
  explicit HillshadeLight(const HillshadeOptions& options);

  // The shade of a facet of gradient `g`: gdaldem's 1 + 254 * cos(angle of
  // incidence), rounded, 1 for facets turned away from the light; 0 (no
  // data) for a NaN gradient.
  uint8_t Shade(const FacetGradient& g) const;

 private:
  double exaggeration_;  // z_factor / scale
  double sin_altitude_, cos_altitude_;
  double sin_azimuth_, cos_azimuth_;
};

// HillshadeLight(options).Shade(g).
uint8_t Shade(const FacetGradient& g, const HillshadeOptions& options);

// The grey-and-alpha PNG of `tile` of `engine`'s dataset lit by `options`,
// after CheckTileSource (`name` is the dataset's, for its errors).
StatusOr<std::string> RenderHillshadeTile(const Engine& engine,
                                          std::string_view name,
                                          const TileAddress& tile,
                                          const HillshadeOptions& options);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_HILLSHADE_H_
