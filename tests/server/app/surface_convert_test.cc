// The Grid request's own arithmetic (FromGridRequest): a box as wide as the
// doubles, cell sizes from huge to tiny. The box, the cells and the header
// stay finite doubles, or the request is refused saying which bound it
// passes, in a message of short numbers.

#include "server/app/surface_convert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace locator {
namespace {

constexpr double kMax = std::numeric_limits<double>::max();

v1::GridRequest GridOver(double min_x, double min_y, double max_x,
                         double max_y) {
  v1::GridRequest request;
  v1::BoundingBox* box = request.mutable_box();
  box->set_min_x(min_x);
  box->set_min_y(min_y);
  box->set_max_x(max_x);
  box->set_max_y(max_y);
  return request;
}

// Every cell centre of `spec` is finite and inside its box.
void ExpectCentresInside(const RasterSpec& spec) {
  for (uint32_t row = 0; row < spec.height; ++row) {
    for (uint32_t col = 0; col < spec.width; ++col) {
      const Point2 q = spec.CellCentre(col, row);
      EXPECT_TRUE(IsFinite(q) && spec.box.Contains(q)) << col << " " << row;
    }
  }
}

TEST(SurfaceConvertTest, WidthAndHeightOverAllTheDoubles) {
  v1::GridRequest request = GridOver(-kMax, -kMax, kMax, kMax);
  request.set_width(4);
  request.set_height(3);
  RasterSpec spec;
  const Status status = FromGridRequest(request, 1000, &spec);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(spec.cell_width(), kMax / 2);
  v1::GridHeader header;
  ToGridHeader(spec, "", &header);
  EXPECT_EQ(header.cell_width(), kMax / 2);
  EXPECT_TRUE(std::isfinite(header.cell_height()));
  ExpectCentresInside(spec);
}

TEST(SurfaceConvertTest, CellSizeOverAllTheDoubles) {
  v1::GridRequest request = GridOver(-kMax, -kMax, kMax, kMax);
  request.set_cell_size(kMax / 2);
  RasterSpec spec;
  const Status status = FromGridRequest(request, 1000, &spec);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(spec.width, 4u);
  EXPECT_EQ(spec.height, 4u);
  EXPECT_EQ(spec.box.max_x, kMax);
  EXPECT_EQ(spec.box.min_y, -kMax);
  ExpectCentresInside(spec);
}

// Whole cells of 0.75 DBL_MAX from -DBL_MAX reach 1.25 DBL_MAX: no double.
TEST(SurfaceConvertTest, CellSizeGrowingTheBoxBeyondTheDoublesIsRefused) {
  v1::GridRequest request = GridOver(-kMax, 0, 0.9 * kMax, 1);
  request.set_cell_size(0.75 * kMax);
  RasterSpec spec;
  const Status status = FromGridRequest(request, 1000, &spec);
  ASSERT_EQ(status.code(), Status::Code::kInvalidArgument) << status.ToString();
  EXPECT_EQ(status.message(),
            "cell_size 1.3482698511467367e+308 grows the box to whole cells "
            "beyond the largest double, 1.7976931348623157e+308: the box's "
            "east and south edges, min_x + width x cell_size and max_y - "
            "height x cell_size, must stay within it");
}

TEST(SurfaceConvertTest, TinyCellSizeIsRefusedInShortNumbers) {
  v1::GridRequest request = GridOver(-1, -1, 1, 1);
  request.set_cell_size(1e-300);
  RasterSpec spec;
  const Status status = FromGridRequest(request, 1000, &spec);
  ASSERT_EQ(status.code(), Status::Code::kResourceExhausted);
  EXPECT_EQ(status.message(),
            "cell_size 1e-300 makes a grid of 1.9999999999999998e+300 x "
            "1.9999999999999998e+300 cells");
}

}  // namespace
}  // namespace locator
