#include "server/bench/noop/noop_services.h"

#include "server/app/proto_convert.h"
#include "server/grpc/call_context.h"
#include "server/grpc/locate_stream_reactor.h"

namespace locator {
namespace {

grpc::ServerUnaryReactor* FinishOk(grpc::CallbackServerContext* context) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(grpc::Status::OK);
  return reactor;
}

Point2 FromProto(const v1::Point& point) {
  return Point2{point.x(), point.y()};
}

}  // namespace

LocateResult CannedAnswer(const Point2& q) {
  LocateResult result;
  result.type = LocationType::kFace;
  result.triangle_id = 0;
  result.vertex_ids = {0, 1, 2};
  result.vertices = {Point2{0, 0}, Point2{1, 0}, Point2{0, 1}};
  result.barycentric = {1 - q.x - q.y, q.x, q.y};
  result.has_value = true;
  result.value = q.x + q.y;
  result.cost.faces_visited = 1;
  return result;
}

NoopLocatorService::NoopLocatorService(const ServingConfig& config)
    : default_deadline_(config.transport.default_deadline),
      batch_locator_(config.threads, config.max_batch_points) {}

grpc::ServerUnaryReactor* NoopLocatorService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  ToLocateResponse(CannedAnswer(FromProto(request->point())), response);
  return FinishOk(context);
}

grpc::ServerUnaryReactor* NoopLocatorService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  batch_locator_.Run(
      *request,
      [](std::span<Point2> points, size_t /*first_index*/,
         std::vector<LocateResult>* results,
         const std::function<bool()>& /*keep_going*/) {
        results->resize(points.size());
        for (size_t i = 0; i < points.size(); ++i) {
          (*results)[i] = CannedAnswer(points[i]);
        }
        return Status::OK();
      },
      UnaryCallControl(context, reactor, default_deadline_), response);
  return reactor;
}

grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>*
NoopLocatorService::LocateStream(grpc::CallbackServerContext* context) {
  return new LocateStreamReactor(
      context, default_deadline_,
      AnswerAtOnce([](const v1::LocateRequest& request, LocateResult* result) {
        *result =
            CannedAnswer(Point2{request.point().x(), request.point().y()});
        return Status::OK();
      }));
}

grpc::ServerUnaryReactor* NoopLocatorService::GetStats(
    grpc::CallbackServerContext* context,
    const v1::GetStatsRequest* /*request*/, v1::GetStatsResponse* response) {
  response->set_strategy("noop");
  return FinishOk(context);
}

grpc::ServerUnaryReactor* NoopLocatorService::Retune(
    grpc::CallbackServerContext* context, const v1::RetuneRequest* /*request*/,
    v1::RetuneResponse* /*response*/) {
  return FinishOk(context);
}

grpc::ServerUnaryReactor* NoopNestedBatchService::LocateNested(
    grpc::CallbackServerContext* context,
    const bench::v1::NestedBatchRequest* request,
    bench::v1::NestedBatchResponse* response) {
  response->mutable_results()->Reserve(request->points_size());
  for (const v1::Point& point : request->points()) {
    ToLocateResponse(CannedAnswer(FromProto(point)), response->add_results());
  }
  return FinishOk(context);
}

}  // namespace locator
