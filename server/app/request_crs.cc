#include "server/app/request_crs.h"

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator {
namespace {

// The calling thread's transformer from `request_crs` to the dataset's.
Status TransformerFor(const Engine& engine, const std::string& request_crs,
                      gis::CrsTransformer** out) {
  return gis::RequestTransformer(request_crs, engine.dataset_info().crs, out);
}

}  // namespace

Status CheckRequestCrs(const Engine& engine, const std::string& crs) {
  if (crs.empty()) return Status::OK();
  gis::CrsTransformer* transformer = nullptr;
  return TransformerFor(engine, crs, &transformer);
}

Status PointsInDatasetCrs(const Engine& engine, const std::string& crs,
                          std::span<Point2> points, size_t first_index) {
  if (crs.empty()) return Status::OK();
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(TransformerFor(engine, crs, &transformer));
  return transformer->ToDataset(points, first_index);
}

Status PointsInRequestCrs(const Engine& engine, const std::string& crs,
                          std::span<Point2> points) {
  if (crs.empty()) return Status::OK();
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(TransformerFor(engine, crs, &transformer));
  return transformer->ToRequest(points);
}

Status LocateBatchWhereDefined(const Engine& engine,
                               const QueryOptions& options,
                               std::span<Point2> points,
                               std::vector<LocateResult>* results,
                               const std::function<bool()>& keep_going) {
  if (options.crs.empty()) {
    return engine.LocateBatch(points, results, keep_going,
                              options.interpolation, options.detail);
  }
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(TransformerFor(engine, options.crs, &transformer));
  transformer->ToDatasetWhereDefined(points);
  // The engine wants finite points only: the defined ones are located
  // together and put back in their places.
  std::vector<Point2> defined;
  std::vector<size_t> places;
  for (size_t i = 0; i < points.size(); ++i) {
    if (std::isfinite(points[i].x) && std::isfinite(points[i].y)) {
      defined.push_back(points[i]);
      places.push_back(i);
    }
  }
  std::vector<LocateResult> located;
  RETURN_IF_ERROR(engine.LocateBatch(defined, &located, keep_going,
                                     options.interpolation, options.detail));
  LocateResult outside;
  outside.type = LocationType::kOutsideConvexHull;
  results->assign(points.size(), outside);
  for (size_t j = 0; j < places.size(); ++j) {
    (*results)[places[j]] = located[j];
  }
  return Status::OK();
}

Status LocateInRequestCrs(const Engine& engine, const ShardTiles* tiles,
                          Point2 point, const QueryOptions& options,
                          LocateResult* result) {
  const auto check_served = [&] {
    return tiles == nullptr
               ? Status::OK()
               : tiles->CheckServed(std::span<const Point2>(&point, 1), 0);
  };
  if (options.crs.empty()) {
    RETURN_IF_ERROR(check_served());
    return engine.Locate(point, result, options.interpolation);
  }
  // One transformer for both ways.
  gis::CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(TransformerFor(engine, options.crs, &transformer));
  RETURN_IF_ERROR(transformer->ToDataset(std::span<Point2>(&point, 1)));
  RETURN_IF_ERROR(check_served());
  RETURN_IF_ERROR(engine.Locate(point, result, options.interpolation));
  if (!options.vertices_in_request_crs) return Status::OK();
  return transformer->ToRequest(result->vertices);
}

}  // namespace locator
