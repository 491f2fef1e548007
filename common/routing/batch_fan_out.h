// FanOutBatch: a LocateBatch split by shard (batch_split.h) sent to every
// shard with points at once, and the answers merged in input order: what
// the clients that route (ShardRoutes) and the router (ShardRouter) do with
// a batch. How a part reaches its shard is the caller's (ShardCalls). The
// first failing part decides the outcome, naming its shard, and cancels
// the others; the outcome is reported once, after every part has answered.
//
// Thread-safety: the parts' callbacks may run on any thread at once; the
// state they share is guarded by a mutex.

#ifndef LOCATOR_COMMON_ROUTING_BATCH_FAN_OUT_H_
#define LOCATOR_COMMON_ROUTING_BATCH_FAN_OUT_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "common/routing/batch_split.h"
#include "locator/v1/locator.pb.h"

namespace locator {

struct ShardCalls {
  using Done = std::function<void(grpc::Status)>;
  // The context of one part's call (its deadline and metadata). Every
  // part's context exists before the first part starts, so that a failing
  // part can cancel the others.
  std::function<std::shared_ptr<grpc::ClientContext>()> new_context;
  // Starts `part` (the fan-out's own copy, which the caller may adjust)
  // on shard `shard` under `context`, its answer into *answer; `done` runs
  // once with the call's status.
  std::function<void(size_t shard, grpc::ClientContext* context,
                     v1::LocateBatchRequest* part,
                     v1::LocateBatchResponse* answer, Done done)>
      start;
  // The shard's address, named in the error of a part that failed.
  std::function<std::string(size_t shard)> target;
  // Runs `merge` once every part has answered: at once, or elsewhere (a
  // pool, for a large batch).
  std::function<void(std::function<void()> merge)> run_merge;
};

// `status` of a call to shard `shard` at `target`, its message prefixed
// with "shard S (TARGET): " (OK stays OK).
grpc::Status FromShard(size_t shard, const std::string& target,
                       const grpc::Status& status);

// Sends the parts of `split` (of `request`) through `calls` and runs `done`
// once: with the first failing part's status ("shard S (TARGET): ..."), or
// OK with the merged answer in *response (UNAVAILABLE when an answer does
// not match its part). An empty batch is merged at once. `request` and
// `response` must outlive `done`.
void FanOutBatch(const v1::LocateBatchRequest* request, BatchSplit split,
                 v1::LocateBatchResponse* response, ShardCalls calls,
                 ShardCalls::Done done);

}  // namespace locator

#endif  // LOCATOR_COMMON_ROUTING_BATCH_FAN_OUT_H_
