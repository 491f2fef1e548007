// ParseWktCoordinates: the WKT of an OGC API EDR query's `coords`: POINT,
// MULTIPOINT (either "((x y), (x y))" or "(x y, x y)") and LINESTRING of at
// least two points, keywords in any case, two coordinates per point (x
// first: longitude for CRS84).
//
// A small strict parser rather than OGR's (common/gis), which would bring
// GDAL into the HTTP library, accepts much more WKT than EDR's coords
// (collections, curves, Z and M), and reads "nan" and "inf" as numbers.
// It reads left to right without recursion, so no text can nest it deep;
// it stops at `max_points` points and at the first error, which is
// InvalidArgument naming the problem: an unknown or empty geometry, Z/M
// coordinates, a point of the wrong number of coordinates, a coordinate
// that is not a finite number (NaN, inf, 1e999), an unbalanced or
// misplaced parenthesis or comma, text after the geometry.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_SERVER_HTTP_EDR_WKT_COORDINATES_H_
#define LOCATOR_SERVER_HTTP_EDR_WKT_COORDINATES_H_

#include <cstddef>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status_or.h"

namespace locator {

struct WktCoordinates {
  enum class Type { kPoint, kMultiPoint, kLineString };
  Type type = Type::kPoint;
  std::vector<Point2> points;
};

// The geometry of `text`; see above.
StatusOr<WktCoordinates> ParseWktCoordinates(std::string_view text,
                                             size_t max_points);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_EDR_WKT_COORDINATES_H_
