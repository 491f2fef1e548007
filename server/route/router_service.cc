#include "server/route/router_service.h"

#include <optional>
#include <string>
#include <utility>

#include "server/grpc/call_context.h"
#include "server/grpc/locate_stream_reactor.h"
#include "server/route/grid_relay.h"
#include "server/route/shard_streams.h"

namespace locator {
namespace {

// A call without a deadline, whose router has no default either, gets this.
constexpr std::chrono::seconds kLastResortDeadline{60};

// The caller's authorization header, to send on to the shards.
std::optional<std::string> Authorization(
    const grpc::CallbackServerContext& context) {
  const std::optional<std::string_view> header = AuthorizationOf(context);
  return header ? std::optional<std::string>(*header) : std::nullopt;
}

grpc::Status NotRouted(std::string_view method) {
  return grpc::Status(grpc::StatusCode::UNIMPLEMENTED,
                      "the router (locatord --route) does not forward " +
                          std::string(method) +
                          "; call a shard (GetTopology lists them)");
}

}  // namespace

RouterService::RouterService(ShardRouter* router,
                             std::chrono::milliseconds default_deadline)
    : router_(router),
      topology_(&router->topology()),
      default_deadline_(default_deadline) {}

std::shared_ptr<grpc::ClientContext> RouterService::ShardContext(
    const grpc::CallbackServerContext& context) const {
  std::shared_ptr<grpc::ClientContext> shard = topology_->NewContext(
      grpc::ClientContext::FromCallbackServerContext(context));
  if (context.deadline() == std::chrono::system_clock::time_point::max()) {
    shard->set_deadline(std::chrono::system_clock::now() +
                        (default_deadline_.count() > 0
                             ? default_deadline_
                             : std::chrono::milliseconds(kLastResortDeadline)));
  }
  if (std::optional<std::string> authorization = Authorization(context)) {
    shard->AddMetadata("authorization", *authorization);
  }
  return shard;
}

ShardRouter::Call RouterService::CallOf(grpc::CallbackServerContext* context,
                                        grpc::ServerUnaryReactor* reactor) {
  return ShardRouter::Call{
      .authorization = Authorization(*context),
      .new_context = [this, context] { return ShardContext(*context); },
      .finish = [reactor](grpc::Status status) { reactor->Finish(status); }};
}

grpc::ServerUnaryReactor* RouterService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  router_->Locate(request, response, CallOf(context, reactor));
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  router_->LocateBatch(request, response, CallOf(context, reactor));
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::GetTopology(
    grpc::CallbackServerContext* context, const v1::GetTopologyRequest* request,
    v1::GetTopologyResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  router_->GetTopology(request, response, CallOf(context, reactor));
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::Profile(
    grpc::CallbackServerContext* context, const v1::ProfileRequest* request,
    v1::ProfileResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  router_->Profile(request, response, CallOf(context, reactor));
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::GetStats(
    grpc::CallbackServerContext* context, const v1::GetStatsRequest* request,
    v1::GetStatsResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  router_->ForwardWhole(0, CallOf(context, reactor),
                        [&](auto* async, auto* shard_context, auto done) {
                          async->GetStats(shard_context, request, response,
                                          std::move(done));
                        });
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::ListDatasets(
    grpc::CallbackServerContext* context,
    const v1::ListDatasetsRequest* request,
    v1::ListDatasetsResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  router_->ForwardWhole(0, CallOf(context, reactor),
                        [&](auto* async, auto* shard_context, auto done) {
                          async->ListDatasets(shard_context, request, response,
                                              std::move(done));
                        });
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::Retune(
    grpc::CallbackServerContext* context, const v1::RetuneRequest* /*request*/,
    v1::RetuneResponse* /*response*/) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(NotRouted("Retune"));
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::Reload(
    grpc::CallbackServerContext* context, const v1::ReloadRequest* /*request*/,
    v1::ReloadResponse* /*response*/) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(NotRouted("Reload"));
  return reactor;
}

grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>*
RouterService::LocateStream(grpc::CallbackServerContext* context) {
  // Each point is routed as a Locate is, several in flight at once, and
  // sent on a stream to its shard (ShardStreams); the reactor writes their
  // answers in the order of the points. The shard streams' contexts are
  // made now, while the stream is surely alive: a point may reach its
  // shard after the stream has finished.
  std::vector<std::shared_ptr<grpc::ClientContext>> contexts;
  for (size_t s = 0; s < topology_->num_shards(); ++s) {
    contexts.push_back(ShardContext(*context));
  }
  auto streams = std::make_shared<ShardStreams>(topology_, std::move(contexts));
  return new LocateStreamReactor(
      context, default_deadline_,
      [this, context, streams](const v1::LocateRequest& request,
                               LocateStreamReactor::Answer answer) {
        struct Routed {
          v1::LocateRequest request;
          v1::LocateResponse response;
        };
        auto point = std::make_shared<Routed>();
        point->request = request;
        router_->Locate(
            &point->request, &point->response,
            ShardRouter::Call{
                .authorization = Authorization(*context),
                .new_context = nullptr,  // the points go on the streams
                .finish =
                    [point, answer = std::move(answer)](grpc::Status status) {
                      answer(status, &point->response);
                    },
                .send_locate =
                    [streams](size_t shard, const v1::LocateRequest* routed,
                              v1::LocateResponse* response,
                              std::function<void(grpc::Status)> done) {
                      streams->Send(shard, *routed, response, std::move(done));
                    }});
      });
}

grpc::ServerWriteReactor<v1::GridResponse>* RouterService::Grid(
    grpc::CallbackServerContext* context, const v1::GridRequest* request) {
  return new GridRelay(topology_, router_->ShardOfGrid(*request),
                       ShardContext(*context), *request);
}

}  // namespace locator
