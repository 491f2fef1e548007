// The answers of the EDR position and trajectory queries: one parameter,
// "elevation" (the dataset's values), at a list of points, written as a
// CoverageJSON Coverage (https://covjson.org/spec/) or a GeoJSON
// FeatureCollection. A point without a value (outside the hull, the
// domain or the CRS's area of use) has a null value.
//
// CoverageJSON domains: one point is a Point domain (axes x and y), several
// a MultiPoint (a "composite" axis of (x, y) tuples), a line a Trajectory
// (a composite axis of (x, y) tuples: the data has no time, so the
// spec's "t" coordinate is left out). GeoJSON: one Point feature per point
// with the property "elevation" (and "distance" along a line).
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_HTTP_EDR_COVERAGE_JSON_H_
#define LOCATOR_SERVER_HTTP_EDR_COVERAGE_JSON_H_

#include <string>
#include <vector>

#include "common/json_writer.h"
#include "locator/geometry.h"
#include "server/http/edr/edr_parameters.h"

namespace locator {

// The EDR parameter every collection has.
inline constexpr char kElevationParameter[] = "elevation";

// The points of an answer, in `crs`, and their values (NaN: none).
struct CoveragePoints {
  enum class Domain { kPoint, kMultiPoint, kTrajectory };
  Domain domain = Domain::kPoint;
  std::vector<Point2> where;
  std::vector<double> values;
  // Along a trajectory, each point's distance from the first (else empty).
  std::vector<double> distances;
};

// Writes the "elevation" parameter's description (CoverageJSON's
// Parameter object, also an EDR collection's parameter_names entry).
void WriteElevationParameter(JsonWriter* json);

// `points` in `format`.
std::string CoverageText(const CoveragePoints& points, const EdrCrs& crs,
                         EdrFormat format);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_EDR_COVERAGE_JSON_H_
