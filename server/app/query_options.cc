#include "server/app/query_options.h"

#include "common/status_macros.h"
#include "server/app/surface_convert.h"

namespace locator {
namespace {

// What every request with points says alike: the interpolation and the CRS.
template <typename Request>
StatusOr<QueryOptions> CommonOptionsOf(const Request& request) {
  QueryOptions options;
  ASSIGN_OR_RETURN(options.interpolation,
                   FromInterpolation(request.interpolation()));
  options.crs = request.crs();
  return options;
}

}  // namespace

StatusOr<QueryOptions> QueryOptionsOf(const v1::LocateRequest& request) {
  ASSIGN_OR_RETURN(QueryOptions options, CommonOptionsOf(request));
  options.vertices_in_request_crs = request.vertices_in_request_crs();
  return options;
}

StatusOr<QueryOptions> QueryOptionsOf(const v1::LocateBatchRequest& request) {
  ASSIGN_OR_RETURN(QueryOptions options, CommonOptionsOf(request));
  options.detail = request.include_barycentric() || request.include_values()
                       ? Detail::kFull
                       : Detail::kLocation;
  return options;
}

StatusOr<QueryOptions> QueryOptionsOf(const v1::ProfileRequest& request) {
  return CommonOptionsOf(request);
}

}  // namespace locator
