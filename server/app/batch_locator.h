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
// Owns the pool (threads - 1 workers). Thread-safety: Run() may be called
// from any number of threads at once.

#ifndef LOCATOR_SERVER_BATCH_LOCATOR_H_
#define LOCATOR_SERVER_BATCH_LOCATOR_H_

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/status.h"
#include "locator/v1/locator.pb.h"
#include "server/serving/call_deadline.h"
#include "server/serving/worker_pool.h"

namespace locator {

// The checks a LocateBatch passes before anything is located: xs and ys of
// equal length (InvalidArgument), at most `max_points` points
// (ResourceExhausted), finite coordinates (InvalidArgument naming the first
// bad point's index). The router (locatord --route) makes them too, so
// that its errors name the point's index in the whole batch.
[[nodiscard]] Status ValidateBatchRequest(const v1::LocateBatchRequest& request,
                                          size_t max_points);

class BatchLocator {
 public:
  static constexpr size_t kMinShardPoints = 4096;
  static constexpr size_t kBlockPoints = 4096;

  // Locates `points`, the request's points from `first_index` on, into
  // `results` (resized), polling `keep_going` between chunks: the
  // application's (which may transform `points` in place), or the no-op
  // server's canned answers.
  using LocateBatchFn =
      std::function<Status(std::span<Point2> points, size_t first_index,
                           std::vector<LocateResult>* results,
                           const std::function<bool()>& keep_going)>;

  // How one call is carried out, whatever transport brought it (gRPC,
  // HTTP).
  struct CallControl {
    CallDeadline deadline;
    // Whether the client has gone; null when the transport cannot tell.
    std::function<bool()> cancelled;
    // Receives the call's outcome, once, on the thread that finished it.
    std::function<void(const Status&)> finish;
  };

  // Splits large batches across `threads` threads (the caller plus
  // threads - 1 pool workers) and rejects batches above `max_batch_points`;
  // each call stops at its CallControl's deadline.
  BatchLocator(size_t threads, size_t max_batch_points);

  BatchLocator(const BatchLocator&) = delete;
  BatchLocator& operator=(const BatchLocator&) = delete;

  // Runs one LocateBatch call: validates `request` (xs/ys lengths, the
  // point limit, finite coordinates), locates its points with `locate_batch`
  // into `response` while the call is neither cancelled nor past its
  // deadline, and calls control.finish with the outcome (CANCELLED or
  // DEADLINE_EXCEEDED when interrupted), possibly before returning.
  // `request` and `response` must live until then. `check`, if given, runs
  // once the request passed Validate and before anything is located (the
  // application's check of the request's CRS, so that an oversized batch is
  // refused for its size whatever its CRS); its error finishes the call.
  void Run(const v1::LocateBatchRequest& request, LocateBatchFn locate_batch,
           CallControl control, v1::LocateBatchResponse* response,
           const std::function<Status()>& check = nullptr);

  // ValidateBatchRequest() with this locator's point limit. Public for the
  // request fuzzer.
  Status Validate(const v1::LocateBatchRequest& request) const {
    return ValidateBatchRequest(request, max_batch_points_);
  }

 private:
  struct Call;

  size_t ShardCount(size_t points) const;
  static void RunShard(const std::shared_ptr<Call>& call, size_t begin,
                       size_t end);
  static void Complete(Call* call);

  const size_t max_batch_points_;
  WorkerPool pool_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_BATCH_LOCATOR_H_
