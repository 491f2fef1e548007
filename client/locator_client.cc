#include "client/locator_client.h"

#include <utility>

#include "common/grpc_code_name.h"

namespace locator {

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

LocatorClient::LocatorClient(std::shared_ptr<grpc::Channel> channel,
                             std::chrono::milliseconds deadline)
    : stub_(v1::Locator::NewStub(channel)),
      health_(channel),
      deadline_(deadline) {}

grpc::Status LocatorClient::Locate(const Point2& point,
                                   v1::LocateResponse* response) {
  v1::LocateRequest request;
  request.mutable_point()->set_x(point.x);
  request.mutable_point()->set_y(point.y);
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
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->LocateBatch(&context, request, response);
}

grpc::Status LocatorClient::GetStats(v1::GetStatsResponse* response) {
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->GetStats(&context, v1::GetStatsRequest(), response);
}

grpc::Status LocatorClient::Retune(v1::RetuneResponse* response) {
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->Retune(&context, v1::RetuneRequest(), response);
}

grpc::Status LocatorClient::Reload(const std::string& dataset,
                                   v1::ReloadResponse* response) {
  v1::ReloadRequest request;
  request.set_dataset(dataset);
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return stub_->Reload(&context, request, response);
}

grpc::Status LocatorClient::CheckHealth(HealthStatus* status) {
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline_);
  return health_.Check(&context, /*service=*/"", status);
}

void LocatorClient::StartLocate(grpc::ClientContext* context,
                                const v1::LocateRequest* request,
                                v1::LocateResponse* response, Completion done) {
  SetDeadlineFromNow(context, deadline_);
  stub_->async()->Locate(context, request, response, std::move(done));
}

void LocatorClient::StartLocateBatch(grpc::ClientContext* context,
                                     const v1::LocateBatchRequest* request,
                                     v1::LocateBatchResponse* response,
                                     Completion done) {
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
