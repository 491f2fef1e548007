#include "server/grpc/grid_stream.h"

#include <algorithm>
#include <utility>

#include "common/status_mapping.h"
#include "server/app/surface_convert.h"

namespace locator {

GridStream::GridStream(grpc::CallbackServerContext* context,
                       CallDeadline deadline,
                       std::shared_ptr<const Engine> engine,
                       const RasterSpec& spec, const std::string& crs_wkt,
                       WorkerPool* pool, std::shared_ptr<void> keep_alive)
    : context_(context),
      deadline_(deadline),
      engine_(std::move(engine)),
      spec_(spec),
      rows_per_block_(GridRowsPerBlock(spec)),
      blocks_((spec.height + rows_per_block_ - 1) / rows_per_block_),
      pool_(pool),
      keep_alive_(std::move(keep_alive)) {
  ToGridHeader(spec_, crs_wkt, &header_);
  Actions actions;
  {
    MutexLock lock(&mu_);
    actions = Pump();
  }
  Run(actions);
}

void GridStream::RenderBlock(uint32_t block) {
  auto message = std::make_unique<v1::GridResponse>();
  const uint32_t first = block * rows_per_block_;
  const uint32_t rows = std::min(rows_per_block_, spec_.height - first);
  grpc::Status status;
  if (deadline_.Passed()) {
    status = ToGrpcStatus(deadline_.ExceededStatus("rendering the grid"));
  } else if (context_->IsCancelled()) {
    status = grpc::Status(grpc::StatusCode::CANCELLED,
                          "call cancelled while rendering the grid");
  } else {
    message->set_first_row(first);
    message->set_rows(rows);
    message->mutable_values()->Resize(static_cast<int>(rows * spec_.width), 0);
    status = ToGrpcStatus(engine_->RenderRows(
        spec_, first, rows, message->mutable_values()->mutable_data()));
  }
  Actions actions;
  {
    MutexLock lock(&mu_);
    --rendering_;
    if (!status.ok()) {
      if (!failure_.has_value()) failure_ = status;
    } else {
      ready_.push_back(std::move(message));
    }
    actions = Pump();
  }
  Run(actions);
}

void GridStream::OnWriteDone(bool ok) {
  Actions actions;
  {
    MutexLock lock(&mu_);
    in_flight_.reset();
    if (ok) {
      ++written_;
    } else if (!failure_.has_value()) {
      failure_ = grpc::Status(grpc::StatusCode::CANCELLED,
                              "the client went while the grid streamed");
    }
    actions = Pump();
  }
  Run(actions);
}

GridStream::Actions GridStream::Pump() {
  Actions actions;
  if (finished_) return actions;
  if (failure_.has_value()) {
    if (rendering_ == 0 && in_flight_ == nullptr) {
      finished_ = true;
      actions.finish = *failure_;
    }
    return actions;
  }
  if (in_flight_ == nullptr && !ready_.empty()) {
    in_flight_ = std::move(ready_.front());
    ready_.pop_front();
    if (!header_sent_) {
      *in_flight_->mutable_header() = header_;
      header_sent_ = true;
    }
    actions.write = in_flight_.get();
  }
  const size_t threads = std::max<size_t>(1, pool_->size());
  while (next_block_ < blocks_ && rendering_ < threads &&
         ready_.size() + rendering_ < kWindowBlocks) {
    ++rendering_;
    pool_->Submit([this, block = next_block_] { RenderBlock(block); });
    ++next_block_;
  }
  if (written_ == blocks_) {
    finished_ = true;
    actions.finish = grpc::Status::OK;
  }
  return actions;
}

void GridStream::Run(const Actions& actions) {
  if (actions.write != nullptr) StartWrite(actions.write);
  if (actions.finish.has_value()) Finish(*actions.finish);
}

}  // namespace locator
