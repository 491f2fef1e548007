// OpenTopoDataQuery: what an Open Topo Data request asks for
// (https://www.opentopodata.org/api/), read from its fields
// (RequestFields) with Open Topo Data's rules and error messages:
//
//   locations       "lat,lng|lat,lng|..." or a Google encoded polyline
//                   ("enc:" optional, as Open Topo Data: text without a
//                   comma is a polyline); latitudes in [-90, 90] and
//                   longitudes in [-180, 180], so NaN and infinities are
//                   refused by position.
//   path            Google Elevation's name for a path with `samples`; the
//                   same syntax. Either locations or path, not both.
//   samples         an integer >= 2: the points are a path, and the answer
//                   is that many evenly spaced samples along it.
//   interpolation   bilinear (Open Topo Data's default) or linear: locator's
//                   linear interpolation over the triangle; nearest; natural
//                   (natural neighbour, locator's extension). cubic, which
//                   Open Topo Data offers on rasters, is refused.
//   nodata_value    null (default), nan, or an integer: the elevation of a
//                   point outside the data.
//
// How many points a request may have is the server's (LocatorApp's batch
// and sample limits), checked when the call runs.
//
// Thread-safety: plain values and a pure function.

#ifndef LOCATOR_SERVER_HTTP_OPENTOPODATA_OPEN_TOPO_DATA_QUERY_H_
#define LOCATOR_SERVER_HTTP_OPENTOPODATA_OPEN_TOPO_DATA_QUERY_H_

#include <cstdint>
#include <variant>
#include <vector>

#include "locator/geometry.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"
#include "server/http/elevation/request_fields.h"

namespace locator {

struct OpenTopoDataQuery {
  // The elevation of a point outside the data.
  enum class NoData { kNull, kNan };
  // x = longitude, y = latitude, in request order.
  std::vector<Point2> points;
  // 0: answer `points`; >= 2: that many samples along them as a path.
  uint32_t samples = 0;
  v1::Interpolation interpolation = v1::INTERPOLATION_LINEAR;
  std::variant<NoData, int64_t> nodata = NoData::kNull;
};

// The query of `fields`; InvalidArgument with Open Topo Data's messages.
StatusOr<OpenTopoDataQuery> ParseOpenTopoDataQuery(const RequestFields& fields);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_OPENTOPODATA_OPEN_TOPO_DATA_QUERY_H_
