// ElevationGrid: a raster DEM as a plain value, what a raster reader
// produces and the terrain simplifier (server/core/terrain/) consumes. It
// knows nothing of GDAL.
//
// Sample (col, row) sits at
//   x = origin_x + col * step_x,  y = origin_y + row * step_y
// in the dataset's CRS: the pixel centre for PixelIsArea, its corner for
// PixelIsPoint (the reader decides); step_y < 0 for north-up rasters. The
// transform has no rotation. `values` is row-major, width * height long,
// and NaN marks nodata.
//
// Thread-safety: a plain value.

#ifndef LOCATOR_COMMON_ELEVATION_GRID_H_
#define LOCATOR_COMMON_ELEVATION_GRID_H_

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "locator/geometry.h"

namespace locator {

struct ElevationGrid {
  uint32_t width = 0;   // columns
  uint32_t height = 0;  // rows
  double origin_x = 0;
  double origin_y = 0;
  double step_x = 1;
  double step_y = -1;
  // Row-major, width * height samples; NaN marks nodata.
  std::vector<float> values;
  // The coordinate reference system as WKT; empty when the raster has none.
  std::string crs;
  // The path or spec it came from, for stats and messages.
  std::string source;

  uint64_t samples() const { return uint64_t{width} * height; }
  // The index of sample (col, row) in `values`.
  size_t Index(uint32_t col, uint32_t row) const {
    return size_t{row} * width + col;
  }
  // Where sample (col, row) sits, in the dataset's CRS.
  Point2 SampleAt(uint32_t col, uint32_t row) const {
    return Point2{origin_x + col * step_x, origin_y + row * step_y};
  }
  float ValueAt(uint32_t col, uint32_t row) const {
    return values[Index(col, row)];
  }
  // Whether sample (col, row) has data (is not NaN).
  bool IsValid(uint32_t col, uint32_t row) const {
    return !std::isnan(ValueAt(col, row));
  }
  // The number of samples that are not NaN. O(width * height).
  uint64_t ValidSamples() const {
    uint64_t valid = 0;
    for (const float v : values) valid += std::isnan(v) ? 0 : 1;
    return valid;
  }
};

}  // namespace locator

#endif  // LOCATOR_COMMON_ELEVATION_GRID_H_
