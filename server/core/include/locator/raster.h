// RasterSpec: a north-up raster over the surface, as GDAL lays one out.
//
// Row 0 is the northern edge (box.max_y); cell (col, row) holds the value at
// its centre, (min_x + (col + 0.5) * cell_width, max_y - (row + 0.5) *
// cell_height). Cells outside the hull or the domain, and every cell of a
// dataset without values, hold `nodata`.

#ifndef LOCATOR_RASTER_H_
#define LOCATOR_RASTER_H_

#include <cstdint>
#include <limits>

#include "locator/geometry.h"
#include "locator/interpolation.h"
#include "locator/status.h"

namespace locator {

struct RasterSpec {
  BoundingBox box;
  uint32_t width = 0;
  uint32_t height = 0;
  double nodata = std::numeric_limits<double>::quiet_NaN();
  Interpolation interpolation = Interpolation::kLinear;

  // Box width / width and box height / height, also for a box wider or
  // higher than the largest double (infinite only when the cell itself is).
  double cell_width() const;
  double cell_height() const;
  uint64_t cells() const { return uint64_t{width} * height; }
  // The centre of cell (col, row): finite for any box of finite doubles.
  Point2 CellCentre(uint32_t col, uint32_t row) const;
};

// The slope of the surface's facet (the triangle's plane) at a point: the
// value's change per unit of x and of y, in the dataset's units. NaN for
// a point with no facet (outside the hull or the domain, not finite) and
// for every point of a dataset without values.
struct FacetGradient {
  double dz_dx = std::numeric_limits<double>::quiet_NaN();
  double dz_dy = std::numeric_limits<double>::quiet_NaN();
};

// OK if `box` can bound a raster: finite, with min < max on both axes;
// InvalidArgument saying which is not otherwise.
[[nodiscard]] Status CheckRasterBox(const BoundingBox& box);

// OK if `spec` describes a raster: a finite box with min < max on both
// axes, width and height >= 1, and cell sizes that are positive finite
// doubles; InvalidArgument naming the problem otherwise.
[[nodiscard]] Status CheckRasterSpec(const RasterSpec& spec);

}  // namespace locator

#endif  // LOCATOR_RASTER_H_
