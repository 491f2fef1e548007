// The request CRS: points a request sends in another CRS than the
// dataset's (QueryOptions::crs) are transformed to the dataset's CRS once,
// with the calling thread's cached PROJ transformer
// (locator::gis::CrsTransformer::ForThread).
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

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "locator/engine.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/status.h"
#include "server/app/query_options.h"
#include "server/datasets/shard_tiles.h"

namespace locator {

// Checks that the engine's dataset can take points in `crs` (nothing when
// it is empty), with the errors above but a point's; the calling thread's
// transformer is made then.
Status CheckRequestCrs(const Engine& engine, const std::string& crs);

// Transforms `points` from `crs` to the engine's dataset CRS in place;
// nothing when `crs` is empty. points[0] is the request's point
// `first_index`, as an error names it.
Status PointsInDatasetCrs(const Engine& engine, const std::string& crs,
                          std::span<Point2> points, size_t first_index = 0);

// Transforms `points` from the engine's dataset CRS back to `crs` in place
// (nothing when it is empty): the answers of a request whose points were in
// `crs`, e.g. a profile's samples. InvalidArgument naming the first point
// PROJ cannot map.
Status PointsInRequestCrs(const Engine& engine, const std::string& crs,
                          std::span<Point2> points);

// Locates `points` (in options.crs) on `engine` into `results`, polling
// `keep_going`, as Engine::LocateBatch does, but a point outside the area
// of use of options.crs or the dataset's CRS (or one PROJ cannot map) is
// answered kOutsideConvexHull without a value instead of failing the call:
// the elevation APIs answer null there. `points` are transformed in place.
// Points of every tile are answered, on a shard too: the elevation APIs,
// which no client routes, are answered whole by any shard, as profiles,
// grids and terrain tiles are (every shard maps the whole mesh).
Status LocateBatchWhereDefined(const Engine& engine,
                               const QueryOptions& options,
                               std::span<Point2> points,
                               std::vector<LocateResult>* results,
                               const std::function<bool()>& keep_going);

// Locates `point` (in options.crs) on `engine` as `options` say; with
// options.vertices_in_request_crs the result's vertices are returned in
// options.crs.
Status LocateInRequestCrs(const Engine& engine, const ShardTiles* tiles,
                          Point2 point, const QueryOptions& options,
                          LocateResult* result);

}  // namespace locator

#endif  // LOCATOR_SERVER_REQUEST_CRS_H_
