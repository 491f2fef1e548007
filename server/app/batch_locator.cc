#include "server/app/batch_locator.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <sstream>
#include <string>
#include <utility>

#include "common/mutex.h"
#include "locator/engine.h"
#include "server/app/proto_convert.h"
#include "server/serving/call_deadline.h"

namespace locator {
namespace {

Status InterruptedStatus(const CallDeadline& deadline) {
  if (deadline.Passed()) return deadline.ExceededStatus("locating the batch");
  // Not the deadline, so the client went.
  return Status::Cancelled("call cancelled while locating the batch");
}

}  // namespace

// Everything the shards of one call share. The last shard to finish reads
// the others' results, hence the acquire-release countdown.
struct BatchLocator::Call {
  CallControl control;
  const v1::LocateBatchRequest* request = nullptr;
  v1::LocateBatchResponse* response = nullptr;
  BatchAnswerColumns columns;
  LocateBatchFn locate_batch;
  std::function<bool()> keep_going;
  std::atomic<size_t> shards_left{0};
  std::atomic<uint64_t> total_cost{0};
  Mutex failure_mu;
  Status failure GUARDED_BY(failure_mu);  // the first failing shard's status

  void Fail(const Status& status) EXCLUDES(failure_mu) {
    MutexLock lock(&failure_mu);
    if (failure.ok()) failure = status;
  }
};

BatchLocator::BatchLocator(size_t threads, size_t max_batch_points)
    : max_batch_points_(max_batch_points),
      pool_(threads > 1 ? threads - 1 : 0) {}

Status ValidateBatchRequest(const v1::LocateBatchRequest& request,
                            size_t max_points) {
  const int xs = request.xs_size();
  const int ys = request.ys_size();
  if (xs != ys) {
    std::ostringstream msg;
    msg << "xs has " << xs << " values but ys has " << ys
        << "; they must have the same length";
    return Status::InvalidArgument(msg.str());
  }
  if (static_cast<size_t>(xs) > max_points) {
    std::ostringstream msg;
    msg << "batch of " << xs << " points exceeds this server's limit of "
        << max_points << " points per batch";
    return Status::ResourceExhausted(msg.str());
  }
  // Checked here for the whole batch, not per block by the engine, so that
  // the index in the message is the point's index in the request.
  for (int i = 0; i < xs; ++i) {
    const Status s = CheckBatchPoint(Point2{request.xs(i), request.ys(i)},
                                     static_cast<size_t>(i));
    if (!s.ok()) return s;
  }
  return Status::OK();
}

size_t BatchLocator::ShardCount(size_t points) const {
  const size_t threads = pool_.size() + 1;
  return std::clamp<size_t>(points / kMinShardPoints, 1, threads);
}

void BatchLocator::Run(const v1::LocateBatchRequest& request,
                       LocateBatchFn locate_batch, CallControl control,
                       v1::LocateBatchResponse* response,
                       const std::function<Status()>& check) {
  Status invalid = Validate(request);
  if (invalid.ok() && check) invalid = check();
  if (!invalid.ok()) {
    control.finish(invalid);
    return;
  }
  const size_t points = static_cast<size_t>(request.xs_size());
  const size_t shards = ShardCount(points);
  auto call = std::make_shared<Call>();
  // Once false it stays false: cancellation and a passed deadline are final.
  call->keep_going = [deadline = control.deadline,
                      cancelled = control.cancelled] {
    return !(cancelled && cancelled()) && !deadline.Passed();
  };
  call->control = std::move(control);
  call->request = &request;
  call->response = response;
  call->columns = SizeBatchAnswerColumns(request, points, response);
  call->locate_batch = std::move(locate_batch);
  call->shards_left.store(shards, std::memory_order_relaxed);

  // Shard s covers [s * points / shards, (s + 1) * points / shards).
  auto shard_begin = [&](size_t shard) { return shard * points / shards; };
  for (size_t shard = 1; shard < shards; ++shard) {
    pool_.Submit(
        [call, begin = shard_begin(shard), end = shard_begin(shard + 1)] {
          RunShard(call, begin, end);
        });
  }
  RunShard(call, 0, shard_begin(1));
}

void BatchLocator::RunShard(const std::shared_ptr<Call>& call, size_t begin,
                            size_t end) {
  // Reused across calls on this thread: a block's worth, never a batch's.
  thread_local std::vector<Point2> points;
  thread_local std::vector<LocateResult> results;

  const v1::LocateBatchRequest& request = *call->request;
  uint64_t shard_cost = 0;
  for (size_t block = begin; block < end; block += kBlockPoints) {
    if (!call->keep_going()) {
      call->Fail(Status::Unavailable("interrupted"));
      break;
    }
    const size_t block_end = std::min(end, block + kBlockPoints);
    points.clear();
    for (size_t i = block; i < block_end; ++i) {
      points.push_back(Point2{request.xs(static_cast<int>(i)),
                              request.ys(static_cast<int>(i))});
    }
    Status status =
        call->locate_batch(points, block, &results, call->keep_going);
    if (!status.ok()) {
      call->Fail(status);
      break;
    }
    shard_cost += WriteBatchAnswers(results, block, call->columns);
  }
  call->total_cost.fetch_add(shard_cost, std::memory_order_relaxed);
  if (call->shards_left.fetch_sub(1, std::memory_order_acq_rel) == 1) {
    Complete(call.get());
  }
}

void BatchLocator::Complete(Call* call) {
  Status failure;
  {
    MutexLock lock(&call->failure_mu);
    failure = call->failure;
  }
  const std::function<void(const Status&)>& finish = call->control.finish;
  if (failure.ok()) {
    call->response->set_total_cost(
        call->total_cost.load(std::memory_order_relaxed));
    finish(Status::OK());
  } else if (!call->keep_going()) {
    // Whatever failed, the client has gone or stopped waiting.
    finish(InterruptedStatus(call->control.deadline));
  } else {
    finish(failure);
  }
}

}  // namespace locator
