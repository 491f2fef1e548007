// QueryOptions: how a request wants its points answered, made from the
// request once (QueryOptionsOf) and passed down to the request CRS and the
// engine: the interpolation of values, how much of each result is filled,
// and the CRS the request's coordinates are in.
//
// Thread-safety: plain values and free functions.

#ifndef LOCATOR_SERVER_APP_QUERY_OPTIONS_H_
#define LOCATOR_SERVER_APP_QUERY_OPTIONS_H_

#include <string>

#include "locator/interpolation.h"
#include "locator/locate_result.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"

namespace locator {

struct QueryOptions {
  Interpolation interpolation = Interpolation::kLinear;
  // kLocation: no barycentric or value is computed.
  Detail detail = Detail::kFull;
  // The CRS of the request's points; empty: the dataset's.
  std::string crs;
  // Whether a located triangle's vertices are answered in `crs`.
  bool vertices_in_request_crs = false;
};

// The options of a Locate: every detail. InvalidArgument for an
// interpolation this server does not know (a newer client's).
StatusOr<QueryOptions> QueryOptionsOf(const v1::LocateRequest& request);
// The options of a LocateBatch: barycentrics and values only when asked
// for.
StatusOr<QueryOptions> QueryOptionsOf(const v1::LocateBatchRequest& request);
// The options of a Profile.
StatusOr<QueryOptions> QueryOptionsOf(const v1::ProfileRequest& request);

}  // namespace locator

#endif  // LOCATOR_SERVER_APP_QUERY_OPTIONS_H_
