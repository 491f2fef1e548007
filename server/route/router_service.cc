#include "server/route/router_service.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/mutex.h"
#include "common/routing/batch_split.h"
#include "server/app/batch_locator.h"
#include "server/grpc/call_context.h"
#include "server/grpc/status_mapping.h"

namespace locator {
namespace {

// A call without a deadline, whose router has no default either, gets this.
constexpr std::chrono::seconds kLastResortDeadline{60};
// Batches up to this many points are split and merged on gRPC's threads
// (as short as routing one point); larger ones on the router's pool.
constexpr int kInlineBatchPoints = 4096;

// The caller's authorization header, to send on to the shards.
std::optional<std::string> Authorization(
    const grpc::CallbackServerContext& context) {
  const std::optional<std::string_view> header = AuthorizationOf(context);
  return header ? std::optional<std::string>(*header) : std::nullopt;
}

// `status` from shard `shard`, its message naming the shard.
grpc::Status FromShard(const ShardTopology& topology, size_t shard,
                       const grpc::Status& status) {
  if (status.ok()) return status;
  return grpc::Status(status.error_code(), "shard " + std::to_string(shard) +
                                               " (" + topology.target(shard) +
                                               "): " + status.error_message());
}

grpc::Status CannotRouteCrs() {
  return grpc::Status(
      grpc::StatusCode::INVALID_ARGUMENT,
      "the router routes points in the dataset's own coordinates; a request "
      "with a crs must go to a shard or an unsharded server");
}

grpc::Status NotRouted(std::string_view method) {
  return grpc::Status(grpc::StatusCode::UNIMPLEMENTED,
                      "the router (locatord --route) does not forward " +
                          std::string(method) +
                          "; call a shard (GetTopology lists them)");
}

// Finishes a call the router does not forward as soon as it starts.
template <typename Reactor>
class Refusal final : public Reactor {
 public:
  explicit Refusal(const grpc::Status& status) { this->Finish(status); }
  void OnDone() override { delete this; }
};

// The state of one routed LocateBatch: the parts, the shards' answers, and
// what is left to wait for. Lives until the last answer has been merged.
struct BatchFanOut {
  BatchSplit split;
  std::vector<v1::LocateBatchResponse> answers;
  std::vector<std::shared_ptr<grpc::ClientContext>> contexts;
  Mutex mu;
  size_t pending GUARDED_BY(mu) = 0;
  grpc::Status failure GUARDED_BY(mu);
};

}  // namespace

RouterService::RouterService(ShardTopology* topology, size_t threads,
                             std::chrono::milliseconds default_deadline,
                             size_t max_batch_points)
    : topology_(topology),
      default_deadline_(default_deadline),
      max_batch_points_(max_batch_points),
      pool_(threads) {}

std::shared_ptr<grpc::ClientContext> RouterService::ShardContext(
    const grpc::CallbackServerContext& context) const {
  std::shared_ptr<grpc::ClientContext> shard =
      grpc::ClientContext::FromCallbackServerContext(context);
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

grpc::ServerUnaryReactor* RouterService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  // Routing one point is a table lookup: short enough for this thread.
  WithTopology(context, request->dataset(), /*here=*/true, reactor,
               [=, this](const ShardTopology::Routed& routed) {
                 ForwardLocate(context, request, response, reactor, routed);
               });
  return reactor;
}

template <typename Route>
void RouterService::WithTopology(grpc::CallbackServerContext* context,
                                 const std::string& dataset, bool here,
                                 grpc::ServerUnaryReactor* reactor,
                                 Route route) {
  if (here) {
    if (std::shared_ptr<const ShardTopology::Routed> routed =
            topology_->Known(dataset)) {
      route(*routed);
      return;
    }
  }
  // Fetching the topology waits on the shards.
  pool_.Submit([this, context, dataset, reactor, route] {
    std::shared_ptr<const ShardTopology::Routed> routed;
    if (grpc::Status status =
            topology_->Get(dataset, Authorization(*context), &routed);
        !status.ok()) {
      reactor->Finish(status);
      return;
    }
    route(*routed);
  });
}

void RouterService::ForwardLocate(grpc::CallbackServerContext* context,
                                  const v1::LocateRequest* request,
                                  v1::LocateResponse* response,
                                  grpc::ServerUnaryReactor* reactor,
                                  const ShardTopology::Routed& routed) {
  if (!request->crs().empty()) {
    reactor->Finish(CannotRouteCrs());
    return;
  }
  // Without a point the first shard says what is wrong.
  uint32_t shard = 0;
  if (request->has_point()) {
    const Point2 p{request->point().x(), request->point().y()};
    shard = routed.map.ShardOf(p);
    if (shard == ShardMap::kNoShard) {
      reactor->Finish(ToGrpcStatus(
          NoShardFor(routed.map.dataset(), 0, p, routed.map.TileOf(p))));
      return;
    }
  }
  std::shared_ptr<grpc::ClientContext> call = ShardContext(*context);
  topology_->async(shard)->Locate(
      call.get(), request, response,
      [this, call, shard, reactor,
       dataset = request->dataset()](grpc::Status status) {
        if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
          topology_->Forget(dataset);
        }
        reactor->Finish(FromShard(*topology_, shard, status));
      });
}

grpc::ServerUnaryReactor* RouterService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  // A small batch is split on this thread as a point is routed; a large
  // one on the pool.
  WithTopology(context, request->dataset(),
               request->xs_size() <= kInlineBatchPoints, reactor,
               [=, this](const ShardTopology::Routed& routed) {
                 RouteBatch(context, request, response, reactor, routed);
               });
  return reactor;
}

void RouterService::RouteBatch(grpc::CallbackServerContext* context,
                               const v1::LocateBatchRequest* request,
                               v1::LocateBatchResponse* response,
                               grpc::ServerUnaryReactor* reactor,
                               const ShardTopology::Routed& routed) {
  // Checked whole, so that an error names the point's index in the batch
  // (a shard's would name it in its part).
  if (Status valid = ValidateBatchRequest(*request, max_batch_points_);
      !valid.ok()) {
    reactor->Finish(ToGrpcStatus(valid));
    return;
  }
  if (!request->crs().empty()) {
    reactor->Finish(CannotRouteCrs());
    return;
  }
  auto fan = std::make_shared<BatchFanOut>();
  if (Status split = SplitBatch(*request, routed.map, &fan->split);
      !split.ok()) {
    reactor->Finish(ToGrpcStatus(split));
    return;
  }
  const size_t shards = fan->split.parts.size();
  fan->answers.resize(shards);
  fan->contexts.resize(shards);
  std::vector<size_t> called;
  for (size_t s = 0; s < shards; ++s) {
    if (!fan->split.positions[s].empty()) called.push_back(s);
  }
  const auto merge = [this, fan, request, response, reactor] {
    grpc::Status failure;
    {
      MutexLock lock(&fan->mu);
      failure = fan->failure;
    }
    if (!failure.ok()) {
      reactor->Finish(failure);
      return;
    }
    reactor->Finish(
        ToGrpcStatus(MergeBatch(*request, fan->split, fan->answers, response)));
  };
  if (called.empty()) {  // an empty batch
    merge();
    return;
  }
  {
    MutexLock lock(&fan->mu);
    fan->pending = called.size();
  }
  // Every context exists before the first call starts: a failing part
  // cancels the others'.
  for (const size_t s : called) fan->contexts[s] = ShardContext(*context);
  for (const size_t s : called) {
    topology_->async(s)->LocateBatch(
        fan->contexts[s].get(), &fan->split.parts[s], &fan->answers[s],
        [this, fan, s, merge, request,
         dataset = request->dataset()](grpc::Status status) {
          if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
            topology_->Forget(dataset);
          }
          bool first_failure = false, last = false;
          {
            MutexLock lock(&fan->mu);
            first_failure = !status.ok() && fan->failure.ok();
            if (first_failure) fan->failure = FromShard(*topology_, s, status);
            last = --fan->pending == 0;
          }
          if (first_failure && !last) {
            // The other parts are of no use any more (cancelled unlocked: a
            // cancellation may run their callbacks at once).
            for (const auto& other : fan->contexts) {
              if (other != nullptr && other != fan->contexts[s]) {
                other->TryCancel();
              }
            }
          }
          if (!last) return;
          if (request->xs_size() <= kInlineBatchPoints) {
            merge();
          } else {
            pool_.Submit(merge);
          }
        });
  }
}

grpc::ServerUnaryReactor* RouterService::GetTopology(
    grpc::CallbackServerContext* context, const v1::GetTopologyRequest* request,
    v1::GetTopologyResponse* response) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  WithTopology(context, request->dataset(), /*here=*/true, reactor,
               [response, reactor](const ShardTopology::Routed& routed) {
                 *response = routed.topology;
                 reactor->Finish(grpc::Status::OK);
               });
  return reactor;
}

// Forwards a unary call to shard `shard` with `start` (which starts the
// stub's callback method) and finishes the caller's call with its answer.
template <typename Request, typename Response, typename Start>
grpc::ServerUnaryReactor* ForwardUnary(
    grpc::CallbackServerContext* context, ShardTopology* topology,
    std::shared_ptr<grpc::ClientContext> call, size_t shard,
    const Request* request, Response* response, Start start) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  start(topology->async(shard), call.get(), request, response,
        [topology, call, shard, reactor](grpc::Status status) {
          reactor->Finish(FromShard(*topology, shard, status));
        });
  return reactor;
}

grpc::ServerUnaryReactor* RouterService::Profile(
    grpc::CallbackServerContext* context, const v1::ProfileRequest* request,
    v1::ProfileResponse* response) {
  // Any shard answers a profile whole; the first vertex's has its pages.
  size_t shard = 0;
  if (std::shared_ptr<const ShardTopology::Routed> routed =
          topology_->Known(request->dataset());
      routed != nullptr && request->crs().empty() &&
      request->vertices_size() > 0) {
    const uint32_t owner = routed->map.ShardOf(
        {request->vertices(0).x(), request->vertices(0).y()});
    if (owner != ShardMap::kNoShard) shard = owner;
  }
  return ForwardUnary(
      context, topology_, ShardContext(*context), shard, request, response,
      [](auto* async, auto* call, auto* req, auto* resp, auto done) {
        async->Profile(call, req, resp, std::move(done));
      });
}

grpc::ServerUnaryReactor* RouterService::GetStats(
    grpc::CallbackServerContext* context, const v1::GetStatsRequest* request,
    v1::GetStatsResponse* response) {
  return ForwardUnary(
      context, topology_, ShardContext(*context), 0, request, response,
      [](auto* async, auto* call, auto* req, auto* resp, auto done) {
        async->GetStats(call, req, resp, std::move(done));
      });
}

grpc::ServerUnaryReactor* RouterService::ListDatasets(
    grpc::CallbackServerContext* context,
    const v1::ListDatasetsRequest* request,
    v1::ListDatasetsResponse* response) {
  return ForwardUnary(
      context, topology_, ShardContext(*context), 0, request, response,
      [](auto* async, auto* call, auto* req, auto* resp, auto done) {
        async->ListDatasets(call, req, resp, std::move(done));
      });
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
RouterService::LocateStream(grpc::CallbackServerContext* /*context*/) {
  return new Refusal<
      grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>>(
      NotRouted("LocateStream (use LocateBatch)"));
}

grpc::ServerWriteReactor<v1::GridResponse>* RouterService::Grid(
    grpc::CallbackServerContext* /*context*/,
    const v1::GridRequest* /*request*/) {
  return new Refusal<grpc::ServerWriteReactor<v1::GridResponse>>(
      NotRouted("Grid"));
}

}  // namespace locator
