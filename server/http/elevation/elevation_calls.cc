#include "server/http/elevation/elevation_calls.h"

#include <limits>
#include <memory>
#include <utility>

#include "common/status_macros.h"
#include "server/app/request_crs.h"

namespace locator {

bool IsExpensive(size_t points, bool line) {
  return line || points > kCheapPoints;
}

void LocateValues(LocatorApp* app, LocatorApp::Admission call,
                  const ElevationQuery& query, const CallDeadline& deadline,
                  std::function<void(StatusOr<std::vector<double>>)> done) {
  // Both live until the batch has finished, which may be on another thread.
  struct Batch {
    v1::LocateBatchRequest request;
    v1::LocateBatchResponse response;
  };
  auto batch = std::make_shared<Batch>();
  batch->request.set_dataset(call.dataset->name());
  batch->request.set_crs(query.crs);
  batch->request.set_include_values(true);
  batch->request.set_interpolation(query.interpolation);
  batch->request.mutable_xs()->Reserve(static_cast<int>(query.points.size()));
  batch->request.mutable_ys()->Reserve(static_cast<int>(query.points.size()));
  for (const Point2& p : query.points) {
    batch->request.add_xs(p.x);
    batch->request.add_ys(p.y);
  }
  app->LocateBatch(
      std::move(call), batch->request,
      BatchLocator::CallControl{
          .deadline = deadline,
          .cancelled = nullptr,
          .finish =
              [batch, done = std::move(done)](const Status& status) {
                if (!status.ok()) {
                  done(status);
                  return;
                }
                const auto& values = batch->response.values();
                done(std::vector<double>(values.begin(), values.end()));
              }},
      &batch->response, LocatorApp::BatchFor::kElevation);
}

StatusOr<std::vector<LinePoint>> LineValues(const LocatorApp& app,
                                            const LocatorApp::Admission& call,
                                            const ElevationQuery& query,
                                            uint32_t samples) {
  v1::ProfileRequest request;
  request.set_dataset(call.dataset->name());
  request.set_crs(query.crs);
  request.set_samples(samples);
  request.set_interpolation(query.interpolation);
  for (const Point2& p : query.points) {
    v1::Point* vertex = request.add_vertices();
    vertex->set_x(p.x);
    vertex->set_y(p.y);
  }
  v1::ProfileResponse response;
  RETURN_IF_ERROR(app.Profile(call, request, &response));
  const auto& answered =
      samples > 0 ? response.samples() : response.breakpoints();
  std::vector<LinePoint> line;
  line.reserve(answered.size());
  std::vector<Point2> where;
  where.reserve(answered.size());
  for (const v1::ProfilePoint& p : answered) {
    line.push_back(LinePoint{
        .point = {p.point().x(), p.point().y()},
        .distance = p.distance(),
        .value = p.has_value() ? p.value()
                               : std::numeric_limits<double>::quiet_NaN()});
    where.push_back(line.back().point);
  }
  // The answer's points are in the dataset's CRS; the client's are not.
  RETURN_IF_ERROR(PointsInRequestCrs(*call.engine, query.crs, where));
  for (size_t i = 0; i < line.size(); ++i) line[i].point = where[i];
  return line;
}

}  // namespace locator
