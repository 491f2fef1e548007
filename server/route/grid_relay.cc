#include "server/route/grid_relay.h"

#include <utility>

#include "server/route/shard_router.h"

namespace locator {

GridRelay::GridRelay(const ShardTopology* topology, size_t shard,
                     std::shared_ptr<grpc::ClientContext> shard_context,
                     const v1::GridRequest& request)
    : topology_(topology),
      shard_(shard),
      shard_context_(std::move(shard_context)),
      request_(request) {
  topology_->async(shard_)->Grid(shard_context_.get(), &request_, this);
  StartRead(&message_);
  StartCall();
}

void GridRelay::OnReadDone(bool ok) {
  // Not ok: the shard's stream ended; OnDone(status) follows.
  if (!ok) return;
  {
    MutexLock lock(&mu_);
    writing_ = true;
  }
  StartWrite(&message_);
}

void GridRelay::OnWriteDone(bool ok) {
  std::optional<grpc::Status> finish;
  {
    MutexLock lock(&mu_);
    writing_ = false;
    finish = std::move(shard_status_);
  }
  if (finish) {
    Finish(*std::move(finish));
  } else if (ok) {
    StartRead(&message_);
  } else {
    shard_context_->TryCancel();  // the caller went away
  }
}

void GridRelay::OnDone(const grpc::Status& status) {
  grpc::Status finish = FromShard(*topology_, shard_, status);
  bool finish_now = false;
  {
    MutexLock lock(&mu_);
    finish_now = !writing_;
    if (!finish_now) shard_status_ = std::move(finish);
  }
  if (finish_now) Finish(std::move(finish));
  SideDone();
}

void GridRelay::OnDone() { SideDone(); }

void GridRelay::SideDone() {
  if (sides_done_.fetch_add(1, std::memory_order_acq_rel) == 1) delete this;
}

}  // namespace locator
