#include "server/serving/request_crs.h"

#include <span>
#include <string>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/input_text.h"
#include "server/grpc/proto_convert.h"
#include "server/grpc/surface_convert.h"

namespace locator {
namespace {

// The calling thread's transformer from `request_crs` to the dataset's.
// Errors name the request's field.
Status TransformerFor(const Engine& engine, const std::string& request_crs,
                      gis::CrsTransformer** out) {
  const std::string& dataset_crs = engine.dataset_info().crs;
  if (dataset_crs.empty()) {
    return Status::InvalidArgument(
        "crs: the request names CRS " + gis::QuotedCrs(request_crs) +
        " but the dataset has none; send points in the dataset's own "
        "coordinates (no crs)");
  }
  const Status status =
      gis::CrsTransformer::ForThread(request_crs, dataset_crs, out);
  if (status.ok()) return status;
  return Status::InvalidArgument("crs: " + status.message());
}

}  // namespace

Status LocateInRequestCrs(const Engine& engine,
                          const v1::LocateRequest& request,
                          LocateResult* result) {
  Point2 point;
  if (Status status = FromLocateRequest(request, &point); !status.ok()) {
    return status;
  }
  Interpolation how;
  if (Status status = FromInterpolation(request.interpolation(), &how);
      !status.ok()) {
    return status;
  }
  if (request.crs().empty()) return engine.Locate(point, result, how);
  gis::CrsTransformer* transformer = nullptr;
  if (Status status = TransformerFor(engine, request.crs(), &transformer);
      !status.ok()) {
    return status;
  }
  if (Status status = transformer->ToDataset(std::span<Point2>(&point, 1));
      !status.ok()) {
    return status;
  }
  if (Status status = engine.Locate(point, result, how); !status.ok()) {
    return status;
  }
  if (!request.vertices_in_request_crs()) return Status::OK();
  return transformer->ToRequest(result->vertices);
}

Status LineInDatasetCrs(const Engine& engine, const std::string& crs,
                        std::vector<Point2>* line) {
  if (crs.empty()) return Status::OK();
  gis::CrsTransformer* transformer = nullptr;
  if (Status status = TransformerFor(engine, crs, &transformer); !status.ok()) {
    return status;
  }
  return transformer->ToDataset(*line);
}

Status BatchInDatasetCrs(const Engine& engine,
                         const v1::LocateBatchRequest& request,
                         v1::LocateBatchRequest* out) {
  *out = request;
  if (request.xs_size() != request.ys_size()) return Status::OK();
  gis::CrsTransformer* transformer = nullptr;
  if (Status status = TransformerFor(engine, request.crs(), &transformer);
      !status.ok()) {
    return status;
  }
  std::vector<Point2> points(request.xs_size());
  for (int i = 0; i < request.xs_size(); ++i) {
    points[i] = Point2{request.xs(i), request.ys(i)};
  }
  if (Status status = transformer->ToDataset(points); !status.ok()) {
    return status;
  }
  for (int i = 0; i < request.xs_size(); ++i) {
    out->set_xs(i, points[i].x);
    out->set_ys(i, points[i].y);
  }
  return Status::OK();
}

}  // namespace locator
