#include "client/locator_client.h"

#include <future>
#include <utility>

#include "client/shard_routes.h"
#include "common/grpc_code_name.h"

namespace locator {
namespace {

// The scope of a request that carries points: all of it.
template <typename Request>
void ApplyPointScope(const RequestScope& scope, Request* request) {
  request->set_dataset(scope.dataset);
  request->set_crs(scope.crs);
  request->set_interpolation(scope.interpolation);
}

}  // namespace

void SetDeadlineFromNow(grpc::ClientContext* context,
                        std::chrono::milliseconds timeout) {
  context->set_deadline(std::chrono::system_clock::now() + timeout);
}

std::string DescribeRpcError(const grpc::Status& status) {
  return std::string(GrpcCodeName(status.error_code())) + ": " +
         status.error_message();
}

void RequestColumns(const BatchColumns& columns,
                    v1::LocateBatchRequest* request) {
  request->set_include_vertex_ids(columns.vertex_ids);
  request->set_include_barycentric(columns.barycentric);
  request->set_include_values(columns.values);
}

void ApplyScope(const RequestScope& scope, v1::LocateRequest* request) {
  ApplyPointScope(scope, request);
}

void ApplyScope(const RequestScope& scope, v1::LocateBatchRequest* request) {
  ApplyPointScope(scope, request);
}

void ApplyScope(const RequestScope& scope, v1::ProfileRequest* request) {
  ApplyPointScope(scope, request);
}

void ApplyScope(const RequestScope& scope, v1::GridRequest* request) {
  request->set_dataset(scope.dataset);
  request->set_interpolation(scope.interpolation);
}

LocatorClient::LocatorClient(std::shared_ptr<grpc::Channel> channel,
                             std::chrono::milliseconds deadline,
                             RequestScope scope)
    : stub_(v1::Locator::NewStub(channel)),
      health_(channel),
      deadline_(deadline),
      scope_(std::move(scope)) {}

LocatorClient::~LocatorClient() = default;

grpc::Status LocatorClient::RouteByTopology(const ChannelOptions& channel) {
  v1::GetTopologyRequest request;
  request.set_dataset(scope_.dataset);
  v1::GetTopologyResponse topology;
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  if (grpc::Status status = stub_->GetTopology(&context, request, &topology);
      !status.ok()) {
    return status;
  }
  if (topology.shards_size() == 1 && topology.shards(0).target().empty() &&
      topology.complete()) {
    return grpc::Status::OK;  // this server serves all of it
  }
  return ShardRoutes::Create(topology, channel, deadline_, scope_, &routes_);
}

grpc::Status LocatorClient::Locate(const Point2& point,
                                   v1::LocateResponse* response) {
  if (routes_ != nullptr) {
    return routes_->ClientFor(point).Locate(point, response);
  }
  v1::LocateRequest request;
  request.mutable_point()->set_x(point.x);
  request.mutable_point()->set_y(point.y);
  ApplyScope(scope_, &request);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->Locate(&context, request, response);
}

grpc::Status LocatorClient::LocateBatch(std::span<const double> xs,
                                        std::span<const double> ys,
                                        const BatchColumns& columns,
                                        v1::LocateBatchResponse* response) {
  v1::LocateBatchRequest request;
  request.mutable_xs()->Add(xs.begin(), xs.end());
  request.mutable_ys()->Add(ys.begin(), ys.end());
  RequestColumns(columns, &request);
  ApplyScope(scope_, &request);
  if (routes_ != nullptr) {
    std::promise<grpc::Status> answered;
    routes_->StartLocateBatch(
        &request, response,
        [&answered](grpc::Status status) { answered.set_value(status); });
    return answered.get_future().get();
  }
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->LocateBatch(&context, request, response);
}

grpc::Status LocatorClient::GetStats(v1::GetStatsResponse* response) {
  v1::GetStatsRequest request;
  request.set_dataset(scope_.dataset);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->GetStats(&context, request, response);
}

grpc::Status LocatorClient::Retune(v1::RetuneResponse* response) {
  v1::RetuneRequest request;
  request.set_dataset(scope_.dataset);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->Retune(&context, request, response);
}

grpc::Status LocatorClient::Reload(const std::string& spec,
                                   v1::ReloadResponse* response) {
  v1::ReloadRequest request;
  request.set_spec(spec);
  request.set_name(scope_.dataset);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->Reload(&context, request, response);
}

grpc::Status LocatorClient::ListDatasets(v1::ListDatasetsResponse* response) {
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->ListDatasets(&context, v1::ListDatasetsRequest(), response);
}

grpc::Status LocatorClient::Profile(std::span<const Point2> vertices,
                                    uint32_t samples,
                                    v1::ProfileResponse* response) {
  v1::ProfileRequest request;
  for (const Point2& vertex : vertices) {
    v1::Point* added = request.add_vertices();
    added->set_x(vertex.x);
    added->set_y(vertex.y);
  }
  request.set_samples(samples);
  ApplyScope(scope_, &request);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->Profile(&context, request, response);
}

grpc::Status LocatorClient::Grid(v1::GridRequest request,
                                 const GridConsumer& consume) {
  ApplyScope(scope_, &request);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  const std::unique_ptr<grpc::ClientReader<v1::GridResponse>> reader =
      stub_->Grid(&context, request);
  v1::GridResponse message;
  while (reader->Read(&message)) {
    if (!consume(message)) {
      context.TryCancel();
      while (reader->Read(&message)) {
      }
      break;
    }
  }
  return reader->Finish();
}

grpc::Status LocatorClient::CheckHealth(HealthStatus* status) {
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return health_.Check(&context, /*service=*/"", status);
}

void LocatorClient::StartLocate(grpc::ClientContext* context,
                                v1::LocateRequest* request,
                                v1::LocateResponse* response, Completion done) {
  if (routes_ != nullptr) {
    const Point2 point{request->point().x(), request->point().y()};
    routes_->ClientFor(point).StartLocate(context, request, response,
                                          std::move(done));
    return;
  }
  ApplyScope(scope_, request);
  SetDeadlineFromNow(context, deadline_);
  stub_->async()->Locate(context, request, response, std::move(done));
}

void LocatorClient::StartLocateBatch(grpc::ClientContext* context,
                                     v1::LocateBatchRequest* request,
                                     v1::LocateBatchResponse* response,
                                     Completion done) {
  ApplyScope(scope_, request);
  if (routes_ != nullptr) {
    routes_->StartLocateBatch(request, response, std::move(done));
    return;
  }
  SetDeadlineFromNow(context, deadline_);
  stub_->async()->LocateBatch(context, request, response, std::move(done));
}

void LocatorClient::StartLocateStream(
    grpc::ClientContext* context,
    std::chrono::system_clock::time_point stream_deadline,
    StreamReactor* reactor) {
  context->set_deadline(stream_deadline);
  stub_->async()->LocateStream(context, reactor);
}

}  // namespace locator
