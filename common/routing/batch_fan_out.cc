#include "common/routing/batch_fan_out.h"

#include <utility>
#include <vector>

#include "common/mutex.h"

namespace locator {
namespace {

// One batch in flight: its parts, their contexts and answers, and what is
// left to wait for. Lives until the last part has answered and the merge
// has run.
struct FanOut {
  BatchSplit split;
  std::vector<v1::LocateBatchResponse> answers;
  std::vector<std::shared_ptr<grpc::ClientContext>> contexts;
  Mutex mu;
  size_t pending GUARDED_BY(mu) = 0;
  grpc::Status failure GUARDED_BY(mu);
};

}  // namespace

grpc::Status FromShard(size_t shard, const std::string& target,
                       const grpc::Status& status) {
  if (status.ok()) return status;
  return grpc::Status(status.error_code(), "shard " + std::to_string(shard) +
                                               " (" + target +
                                               "): " + status.error_message());
}

void FanOutBatch(const v1::LocateBatchRequest* request, BatchSplit split,
                 v1::LocateBatchResponse* response, ShardCalls calls,
                 ShardCalls::Done done) {
  auto fan = std::make_shared<FanOut>();
  fan->split = std::move(split);
  const size_t shards = fan->split.parts.size();
  fan->answers.resize(shards);
  fan->contexts.resize(shards);
  std::vector<size_t> called;
  for (size_t s = 0; s < shards; ++s) {
    if (!fan->split.positions[s].empty()) called.push_back(s);
  }
  auto merge = [fan, request, response, done = std::move(done)] {
    grpc::Status failure;
    {
      MutexLock lock(&fan->mu);
      failure = fan->failure;
    }
    if (!failure.ok()) return done(failure);
    const Status merged =
        MergeBatch(*request, fan->split, fan->answers, response);
    done(merged.ok()
             ? grpc::Status::OK
             : grpc::Status(grpc::StatusCode::UNAVAILABLE, merged.message()));
  };
  if (called.empty()) return merge();
  {
    MutexLock lock(&fan->mu);
    fan->pending = called.size();
  }
  for (const size_t s : called) fan->contexts[s] = calls.new_context();
  auto shared = std::make_shared<const ShardCalls>(std::move(calls));
  for (const size_t s : called) {
    shared->start(s, fan->contexts[s].get(), &fan->split.parts[s],
                  &fan->answers[s],
                  [fan, s, merge, shared](grpc::Status status) {
                    bool first_failure = false, last = false;
                    {
                      MutexLock lock(&fan->mu);
                      first_failure = !status.ok() && fan->failure.ok();
                      if (first_failure) {
                        fan->failure = FromShard(s, shared->target(s), status);
                      }
                      last = --fan->pending == 0;
                    }
                    if (first_failure && !last) {
                      // The other parts are of no use any more (cancelled
                      // unlocked: a cancellation may run their callbacks at
                      // once).
                      for (const auto& other : fan->contexts) {
                        if (other != nullptr && other != fan->contexts[s]) {
                          other->TryCancel();
                        }
                      }
                    }
                    if (last) shared->run_merge(merge);
                  });
  }
}

}  // namespace locator
