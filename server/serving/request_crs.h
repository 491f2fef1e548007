// The request CRS: points a request sends in another CRS than the
// dataset's (LocateRequest.crs, LocateBatchRequest.crs) are transformed to
// the dataset's CRS once per request, with the calling thread's cached PROJ
// transformer (locator::gis::CrsTransformer::ForThread).
//
// The request's CRS is held to the request CRS policy
// (common/gis/request_crs_policy.h): bounded in length, and PROJ opens no
// file for it outside its own data directories; a CRS that failed once
// fails again without PROJ being asked.
//
// Errors are InvalidArgument: an unknown CRS, one too long or naming a file
// PROJ may not open, a CRS sent to a dataset that has none (these start
// "crs: "), a point outside the transformation's area of use (named by its
// index). Non-finite points are left as they are, for the engine's own
// check and message.
//
// Thread-safety: free functions; may run on any thread.

#ifndef LOCATOR_SERVER_REQUEST_CRS_H_
#define LOCATOR_SERVER_REQUEST_CRS_H_

#include <string>
#include <vector>

#include "locator/engine.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/status.h"
#include "locator/v1/locator.pb.h"

namespace locator {

// Locates request.point on `engine` (values interpolated as the request
// says), transformed from request.crs when it
// is set; with vertices_in_request_crs the result's vertices are returned
// in request.crs.
Status LocateInRequestCrs(const Engine& engine,
                          const v1::LocateRequest& request,
                          LocateResult* result);

// Transforms `line` from `crs` to the engine's dataset CRS; nothing when
// `crs` is empty.
Status LineInDatasetCrs(const Engine& engine, const std::string& crs,
                        std::vector<Point2>* line);

// *out = `request` with xs and ys transformed from request.crs (which must
// be set) to the engine's dataset CRS. Columns of unequal length are copied
// untransformed, for the batch's own validation to reject.
Status BatchInDatasetCrs(const Engine& engine,
                         const v1::LocateBatchRequest& request,
                         v1::LocateBatchRequest* out);

}  // namespace locator

#endif  // LOCATOR_SERVER_REQUEST_CRS_H_
