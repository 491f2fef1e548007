#include "client/shard_routes.h"

#include <utility>

#include "common/mutex.h"
#include "common/routing/batch_split.h"

namespace locator {
namespace {

// One routed LocateBatch in flight: its parts, their contexts and answers.
// Lives until the last part has answered.
struct BatchParts {
  BatchSplit split;
  std::vector<v1::LocateBatchResponse> answers;
  std::vector<std::unique_ptr<grpc::ClientContext>> contexts;
  Mutex mu;
  size_t pending GUARDED_BY(mu) = 0;
  grpc::Status failure GUARDED_BY(mu);
};

}  // namespace

ShardRoutes::ShardRoutes(ShardMap map,
                         std::vector<std::unique_ptr<LocatorClient>> shards)
    : map_(std::move(map)), shards_(std::move(shards)) {}

grpc::Status ShardRoutes::Create(const v1::GetTopologyResponse& topology,
                                 const ChannelOptions& channel,
                                 std::chrono::milliseconds deadline,
                                 const RequestScope& scope,
                                 std::unique_ptr<ShardRoutes>* routes) {
  StatusOr<ShardMap> map = ShardMap::FromTopology(topology);
  if (!map.ok()) {
    return grpc::Status(grpc::StatusCode::FAILED_PRECONDITION,
                        map.status().message());
  }
  if (!map->complete()) {
    return grpc::Status(
        grpc::StatusCode::FAILED_PRECONDITION,
        "the topology of dataset '" + map->dataset() +
            "' is incomplete (some tiles have no shard): ask a router "
            "(locatord --route) for it, or call it without routing");
  }
  std::vector<std::unique_ptr<LocatorClient>> shards;
  for (size_t s = 0; s < map->num_shards(); ++s) {
    ChannelOptions options = channel;
    if (!map->target(s).empty()) options.target = map->target(s);
    shards.push_back(std::make_unique<LocatorClient>(
        CreateLocatorChannel(options), deadline, scope));
  }
  routes->reset(new ShardRoutes(*std::move(map), std::move(shards)));
  return grpc::Status::OK;
}

LocatorClient& ShardRoutes::ClientFor(const Point2& point) const {
  return *shards_[map_.ShardOf(point)];
}

void ShardRoutes::StartLocateBatch(const v1::LocateBatchRequest* request,
                                   v1::LocateBatchResponse* response,
                                   Completion done) const {
  auto parts = std::make_shared<BatchParts>();
  if (Status split = SplitBatch(*request, map_, &parts->split); !split.ok()) {
    done(grpc::Status(split.code() == Status::Code::kFailedPrecondition
                          ? grpc::StatusCode::FAILED_PRECONDITION
                          : grpc::StatusCode::INVALID_ARGUMENT,
                      split.message()));
    return;
  }
  const size_t shards = parts->split.parts.size();
  parts->answers.resize(shards);
  std::vector<size_t> called;
  for (size_t s = 0; s < shards; ++s) {
    parts->contexts.push_back(std::make_unique<grpc::ClientContext>());
    if (!parts->split.positions[s].empty()) called.push_back(s);
  }
  const auto finish = [parts, request, response, done] {
    grpc::Status failure;
    {
      MutexLock lock(&parts->mu);
      failure = parts->failure;
    }
    if (!failure.ok()) return done(failure);
    const Status merged =
        MergeBatch(*request, parts->split, parts->answers, response);
    done(merged.ok()
             ? grpc::Status::OK
             : grpc::Status(grpc::StatusCode::UNAVAILABLE, merged.message()));
  };
  if (called.empty()) return finish();  // an empty batch
  {
    MutexLock lock(&parts->mu);
    parts->pending = called.size();
  }
  for (const size_t s : called) {
    shards_[s]->StartLocateBatch(
        parts->contexts[s].get(), &parts->split.parts[s], &parts->answers[s],
        [this, parts, s, finish](grpc::Status status) {
          bool first_failure = false, last = false;
          {
            MutexLock lock(&parts->mu);
            first_failure = !status.ok() && parts->failure.ok();
            if (first_failure) {
              parts->failure = grpc::Status(
                  status.error_code(), "shard " + std::to_string(s) + " (" +
                                           map_.target(s) +
                                           "): " + status.error_message());
            }
            last = --parts->pending == 0;
          }
          if (first_failure && !last) {
            for (size_t other = 0; other < parts->contexts.size(); ++other) {
              if (other != s) parts->contexts[other]->TryCancel();
            }
          }
          if (last) finish();
        });
  }
}

}  // namespace locator
