// The calls the elevation APIs (Open Topo Data, OGC API EDR) make on the
// application, whatever their request and answer shapes: values at points
// and along a line, with points in a request CRS (or the dataset's own,
// when it is empty), and the lane each runs in. They run the application's
// own methods (LocatorApp::LocateBatch, LocatorApp::Profile), so limits,
// deadlines, tokens and errors are the locator.v1 ones.
//
// Thread-safety: free functions; call them on a lane thread of an admitted
// call.

#ifndef LOCATOR_SERVER_HTTP_ELEVATION_ELEVATION_CALLS_H_
#define LOCATOR_SERVER_HTTP_ELEVATION_ELEVATION_CALLS_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "locator/geometry.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"
#include "server/app/locator_app.h"
#include "server/serving/call_deadline.h"

namespace locator {

// The request CRS of latitude/longitude points (x = longitude, as the
// application's request CRSs are in traditional GIS order).
inline constexpr char kLonLatCrs[] = "EPSG:4326";

// A call of at most this many points, and no line, runs in the cheap lane:
// one block of the batch locator.
inline constexpr size_t kCheapPoints = 4096;

// What to compute.
struct ElevationQuery {
  // In `crs`; for a line, its vertices.
  std::vector<Point2> points;
  // The points' CRS ("" the dataset's).
  std::string crs;
  v1::Interpolation interpolation = v1::INTERPOLATION_LINEAR;
};

// Whether a call on `points` points (the vertices of a line when `line`)
// runs in the expensive lane.
bool IsExpensive(size_t points, bool line);

// The values at query.points (NaN: outside the hull, the domain or the
// CRSs' area of use, or a dataset without values), given to `done` on the
// thread that finishes the batch.
void LocateValues(LocatorApp* app, LocatorApp::Admission call,
                  const ElevationQuery& query, const CallDeadline& deadline,
                  std::function<void(StatusOr<std::vector<double>>)> done);

// A point of a line's answer: where (in the query's CRS), how far along
// the line (in the dataset's CRS units), and the value (NaN in a gap).
struct LinePoint {
  Point2 point;
  double distance = 0;
  double value = 0;
};

// The line through query.points: `samples` evenly spaced samples along it,
// or its exact breakpoints when `samples` is 0 (LocatorApp::Profile).
StatusOr<std::vector<LinePoint>> LineValues(const LocatorApp& app,
                                            const LocatorApp::Admission& call,
                                            const ElevationQuery& query,
                                            uint32_t samples);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_ELEVATION_ELEVATION_CALLS_H_
