// Raster DEMs made at test time with GDAL's C++ API (no binary files in the
// repository), and the terrain they hold.
//
// Thread-safety: free functions; each test uses its own directory.

#ifndef LOCATOR_TESTS_COMMON_GIS_RASTER_FIXTURES_H_
#define LOCATOR_TESTS_COMMON_GIS_RASTER_FIXTURES_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace locator::gis::testing {

struct DemFixture {
  uint32_t width = 0;
  uint32_t height = 0;
  // GDAL's geotransform: (origin x, pixel width, 0, origin y, 0, pixel
  // height), the origin being the outer corner of pixel (0, 0).
  std::array<double, 6> geotransform = {0, 1, 0, 0, 0, -1};
  // Row-major, width * height, in the file's data type's range.
  std::vector<double> values;
  // GDAL's name of the band's type: "Float32", "Int16", "CFloat32", ...
  std::string type = "Float32";
  bool has_nodata = false;
  double nodata = 0;
  // "EPSG:32633" or WKT; empty: no CRS.
  std::string crs;
  // "Area", "Point" or empty (the AREA_OR_POINT metadata item).
  std::string area_or_point;
  double scale = 1;
  double offset = 0;
  // Bands written, each holding `values` (band b adds 1000 * (b - 1)).
  int bands = 1;
  // A per-dataset mask band (GDAL's .msk), its pixels valid where true;
  // empty: none.
  std::vector<bool> mask;
};

// Writes `dem` as a GeoTIFF at `path`; a failure fails the test.
void WriteDem(const std::string& path, const DemFixture& dem);

// A hill of `width` x `height` pixels of `cell` metres around (500000,
// 5500000) in UTM 33N (EPSG:32633), Float32: z = 400 + 300 *
// exp(-r^2 / 2 sigma^2) plus a gentle ripple, sigma a third of the width.
DemFixture HillDem(uint32_t width, uint32_t height, double cell);

// Sets the pixels of [col0, col1) x [row0, row1) of `dem` to its nodata
// value (which it must have).
void PunchHole(DemFixture* dem, uint32_t col0, uint32_t row0, uint32_t col1,
               uint32_t row1);

}  // namespace locator::gis::testing

#endif  // LOCATOR_TESTS_COMMON_GIS_RASTER_FIXTURES_H_
