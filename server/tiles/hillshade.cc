#include "server/tiles/hillshade.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "common/text_fields.h"
#include "server/tiles/png_image.h"
#include "server/tiles/terrain_tile.h"

namespace locator {
namespace {

// The largest z factor and scale taken: beyond it the relief is a flat
// grey or a black-and-white pattern, and squares of gradients near the
// largest double would overflow.
constexpr double kMaxFactor = 1e9;

// Reads query parameter `name`'s `text` into *value (left alone when
// `text` is empty) and checks that it lies in [low, high] (or (0, high]
// when `positive`).
Status ParseOption(std::string_view name, std::string_view text, double low,
                   double high, bool positive, double* value) {
  if (text.empty()) return Status::OK();
  double parsed = 0;
  const bool in_range = ParseNumber(text, &parsed) == NumberKind::kFinite &&
                        (positive ? parsed > 0 : parsed >= low) &&
                        parsed <= high;
  if (!in_range) {
    return Status::InvalidArgument(
        std::string(name) + " " + QuotedInput(text) + " must be a number " +
        (positive ? "above 0" : "from " + NumberText(low)) + " to " +
        NumberText(high));
  }
  *value = parsed;
  return Status::OK();
}

}  // namespace

StatusOr<HillshadeOptions> ParseHillshadeOptions(std::string_view azimuth,
                                                 std::string_view altitude,
                                                 std::string_view z_factor,
                                                 std::string_view scale) {
  HillshadeOptions options;
  RETURN_IF_ERROR(ParseOption("azimuth", azimuth, 0, 360, /*positive=*/false,
                              &options.azimuth));
  RETURN_IF_ERROR(ParseOption("altitude", altitude, 0, 90, /*positive=*/false,
                              &options.altitude));
  RETURN_IF_ERROR(ParseOption("z_factor", z_factor, 0, kMaxFactor,
                              /*positive=*/true, &options.z_factor));
  RETURN_IF_ERROR(ParseOption("scale", scale, 0, kMaxFactor,
                              /*positive=*/true, &options.scale));
  return options;
}

std::string HillshadeVariant(const HillshadeOptions& options) {
  return "hillshade-" + NumberText(options.azimuth) + "-" +
         NumberText(options.altitude) + "-" + NumberText(options.z_factor) +
         "-" + NumberText(options.scale);
}

HillshadeLight::HillshadeLight(const HillshadeOptions& options) {
  constexpr double kRadians = std::numbers::pi / 180;
  const double altitude = options.altitude * kRadians;
  const double azimuth = options.azimuth * kRadians;
  exaggeration_ = options.z_factor / options.scale;
  sin_altitude_ = std::sin(altitude);
  cos_altitude_ = std::cos(altitude);
  sin_azimuth_ = std::sin(azimuth);
  cos_azimuth_ = std::cos(azimuth);
}

// gdaldem's GDALHillshadeAlg, written for a known gradient: with p and q
// the slopes east and north (dz/dx and dz/dy times z_factor / scale), the
// light's direction (cos alt sin az, cos alt cos az, sin alt) and the
// facet's normal (-p, -q, 1) / sqrt(1 + p^2 + q^2) meet at the angle whose
// cosine is returned (gdaldem's Horn window gives x = -p and y = q, and the
// same expression).
uint8_t HillshadeLight::Shade(const FacetGradient& g) const {
  if (std::isnan(g.dz_dx) || std::isnan(g.dz_dy)) return 0;
  const double p = g.dz_dx * exaggeration_;
  const double q = g.dz_dy * exaggeration_;
  const double facing = q * cos_azimuth_ + p * sin_azimuth_;
  // hypot, not sqrt(1 + p*p + q*q): p*p overflows for slopes past 1e154.
  const double cosine = (sin_altitude_ - cos_altitude_ * facing) /
                        std::hypot(1.0, std::hypot(p, q));
  // A vertical facet (an infinite slope) is lit edge-on: cosine 0.
  const double lit = std::isnan(cosine) ? 0 : cosine;
  if (!(lit > 0)) return 1;
  return static_cast<uint8_t>(std::min(255.0, std::floor(1 + 254 * lit + 0.5)));
}

uint8_t Shade(const FacetGradient& g, const HillshadeOptions& options) {
  return HillshadeLight(options).Shade(g);
}

StatusOr<std::string> RenderHillshadeTile(const Engine& engine,
                                          std::string_view name,
                                          const TileAddress& tile,
                                          const HillshadeOptions& options) {
  RETURN_IF_ERROR(CheckTileSource(engine, name));
  std::vector<Point2> pixels;
  RETURN_IF_ERROR(TilePixelsInDatasetCrs(engine, tile, &pixels));
  std::vector<FacetGradient> gradients(pixels.size());
  RETURN_IF_ERROR(
      engine.RenderGradients(pixels, TileAddress::kPixels, gradients.data()));
  const HillshadeLight light(options);
  std::vector<uint8_t> grey_alpha(gradients.size() * 2);
  // Neighbouring pixels mostly lie on one facet: its shade is reused.
  FacetGradient last{0, 0};
  uint8_t last_shade = light.Shade(last);
  for (size_t i = 0; i < gradients.size(); ++i) {
    const FacetGradient& g = gradients[i];
    if (g.dz_dx != last.dz_dx || g.dz_dy != last.dz_dy) {
      last = g;
      last_shade = light.Shade(g);
    }
    const uint8_t shade = last_shade;
    if (shade == 0) continue;  // no facet: stays transparent
    grey_alpha[2 * i] = shade;
    grey_alpha[2 * i + 1] = 255;
  }
  return EncodePng(grey_alpha, TileAddress::kPixels, TileAddress::kPixels,
                   PngColor::kGrayAlpha);
}

}  // namespace locator
