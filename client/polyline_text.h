// ParsePolyline: a polyline as people write it on a command line, either as
// coordinate pairs, "x0,y0 x1,y1 ..." (pairs separated by whitespace), or as
// WKT, "LINESTRING (x0 y0, x1 y1, ...)" (case-insensitive; "LINESTRING Z"
// with a third coordinate per vertex, which is dropped).
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CLIENT_POLYLINE_TEXT_H_
#define LOCATOR_CLIENT_POLYLINE_TEXT_H_

#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

// Parses `text` into `vertices`. InvalidArgument naming the problem: a
// coordinate that is not a number, a pair without its comma, a vertex with
// the wrong number of coordinates, WKT that is not a LINESTRING or is
// unbalanced, fewer than 2 vertices. Values that parse (NaN included) are
// the server's to judge.
Status ParsePolyline(std::string_view text, std::vector<Point2>* vertices);

}  // namespace locator

#endif  // LOCATOR_CLIENT_POLYLINE_TEXT_H_
