// BatchLocator: runs one columnar LocateBatch request across the calling
// thread and a small worker pool, and fills the response's columns.
//
// A batch of n points is cut into min(threads, n / kMinShardPoints) contiguous
// shards (at least one). Shard 0 runs on the calling thread (the gRPC callback
// thread), the others on the pool; whichever shard finishes last finishes the
// RPC, so no thread ever waits for another. Each shard locates its points in
// blocks of kBlockPoints, so its buffers stay small and cache-resident however
// large the batch, and checks between blocks whether to keep going.
//
// Owns the pool (threads - 1 workers). Thread-safety: Serve() may be called
// from any number of threads at once.

#ifndef LOCATOR_SERVER_BATCH_LOCATOR_H_
#define LOCATOR_SERVER_BATCH_LOCATOR_H_

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "common/geometry.h"
#include "common/status.h"
#include "locator/v1/locator.pb.h"
#include "server/core/locate_result.h"
#include "server/worker_pool.h"

namespace locator {

class BatchLocator {
 public:
  static constexpr size_t kMinShardPoints = 4096;
  static constexpr size_t kBlockPoints = 4096;

  // Locates `points` into `results` (resized), polling `keep_going` between
  // chunks: Engine::LocateBatch, or the no-op server's canned answers.
  using LocateBatchFn = std::function<Status(
      std::span<const Point2> points, std::vector<LocateResult>* results,
      const std::function<bool()>& keep_going)>;

  // Splits large batches across `threads` threads (the caller plus
  // threads - 1 pool workers), rejects batches above `max_batch_points` and
  // stops a batch whose client set no deadline after `default_deadline`
  // (zero: never).
  BatchLocator(size_t threads, size_t max_batch_points,
               std::chrono::milliseconds default_deadline);

  BatchLocator(const BatchLocator&) = delete;
  BatchLocator& operator=(const BatchLocator&) = delete;

  // Serves one LocateBatch call: validates `request` (xs/ys lengths, the
  // point limit, finite coordinates), locates its points with `locate_batch`
  // into `response` while the call is neither cancelled nor past its
  // deadline (see CallDeadline), and finishes the returned reactor with the
  // outcome (CANCELLED or DEADLINE_EXCEEDED when interrupted).
  grpc::ServerUnaryReactor* Serve(grpc::CallbackServerContext* context,
                                  const v1::LocateBatchRequest& request,
                                  LocateBatchFn locate_batch,
                                  v1::LocateBatchResponse* response);

  // The checks Serve() makes before locating anything: xs and ys of equal
  // length (InvalidArgument), at most max_batch_points points
  // (ResourceExhausted), finite coordinates (InvalidArgument naming the first
  // bad point's index). Public for the request fuzzer.
  Status Validate(const v1::LocateBatchRequest& request) const;

 private:
  struct Call;

  size_t ShardCount(size_t points) const;
  static void RunShard(const std::shared_ptr<Call>& call, size_t begin,
                       size_t end);
  static void Complete(Call* call);

  const size_t max_batch_points_;
  const std::chrono::milliseconds default_deadline_;
  WorkerPool pool_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_BATCH_LOCATOR_H_
