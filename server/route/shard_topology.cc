#include "server/route/shard_topology.h"

#include <google/protobuf/util/message_differencer.h>

#include <utility>

namespace locator {
namespace {

// Whether two shards' answers describe the same tiles of the same set.
bool SameTiles(const v1::GetTopologyResponse& a,
               const v1::GetTopologyResponse& b) {
  using google::protobuf::util::MessageDifferencer;
  return a.tiled() == b.tiled() && a.grid_level() == b.grid_level() &&
         a.fingerprint() == b.fingerprint() && a.crs() == b.crs() &&
         MessageDifferencer::Equals(a.bounds(), b.bounds()) &&
         a.tiles_size() == b.tiles_size() &&
         std::equal(a.tiles().begin(), a.tiles().end(), b.tiles().begin(),
                    [](const v1::TopologyTile& x, const v1::TopologyTile& y) {
                      return MessageDifferencer::Equals(x, y);
                    });
}

}  // namespace

ShardTopology::ShardTopology(const std::vector<std::string>& targets,
                             const ChannelOptions& channel,
                             std::chrono::milliseconds fetch_deadline)
    : targets_(targets), fetch_deadline_(fetch_deadline) {
  for (const std::string& target : targets_) {
    ChannelOptions options = channel;
    options.target = target;
    stubs_.push_back(v1::Locator::NewStub(CreateLocatorChannel(options)));
  }
}

ShardTopology::~ShardTopology() { contexts_.WaitUntilNone(); }

grpc::Status ShardTopology::Get(const std::string& dataset,
                                const std::optional<std::string>& authorization,
                                std::shared_ptr<const Routed>* routed) {
  if ((*routed = Known(dataset)) != nullptr) return grpc::Status::OK;
  // Fetched unlocked: two first calls may both fetch; either answer does.
  const grpc::Status status = Fetch(dataset, authorization, routed);
  if (status.ok()) {
    MutexLock lock(&mu_);
    known_[dataset] = *routed;
  }
  return status;
}

std::shared_ptr<const ShardTopology::Routed> ShardTopology::Known(
    const std::string& dataset) const {
  MutexLock lock(&mu_);
  const auto it = known_.find(dataset);
  return it == known_.end() ? nullptr : it->second;
}

void ShardTopology::Forget(const std::string& dataset) {
  MutexLock lock(&mu_);
  known_.erase(dataset);
}

grpc::Status ShardTopology::Fetch(
    const std::string& dataset, const std::optional<std::string>& authorization,
    std::shared_ptr<const Routed>* routed) const {
  std::vector<v1::GetTopologyResponse> answers(stubs_.size());
  v1::GetTopologyRequest request;
  request.set_dataset(dataset);
  for (size_t s = 0; s < stubs_.size(); ++s) {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + fetch_deadline_);
    if (authorization) context.AddMetadata("authorization", *authorization);
    const grpc::Status status =
        stubs_[s]->GetTopology(&context, request, &answers[s]);
    if (!status.ok()) {
      return grpc::Status(status.error_code(),
                          "shard " + std::to_string(s) + " (" + targets_[s] +
                              "): " + status.error_message());
    }
  }
  v1::GetTopologyResponse merged = answers[0];
  merged.clear_shards();
  for (size_t s = 0; s < answers.size(); ++s) {
    if (!SameTiles(answers[0], answers[s])) {
      return grpc::Status(grpc::StatusCode::FAILED_PRECONDITION,
                          "shards 0 (" + targets_[0] + ") and " +
                              std::to_string(s) + " (" + targets_[s] +
                              ") serve different tile sets as dataset '" +
                              answers[0].dataset() + "'");
    }
    v1::TopologyShard* shard = merged.add_shards();
    shard->set_target(targets_[s]);
    if (!merged.tiled()) break;  // served whole: by the first shard
    for (const v1::TopologyShard& listed : answers[s].shards()) {
      shard->mutable_tiles()->MergeFrom(listed.tiles());
    }
  }
  StatusOr<ShardMap> map = ShardMap::FromTopology(merged);
  if (!map.ok()) {
    return grpc::Status(
        grpc::StatusCode::FAILED_PRECONDITION,
        "the shards' topologies do not add up: " + map.status().message());
  }
  merged.set_complete(map->complete());
  *routed = std::make_shared<const Routed>(
      Routed{std::move(merged), *std::move(map)});
  return grpc::Status::OK;
}

}  // namespace locator
