#include "server/route/grid_collector.h"

#include <algorithm>
#include <string>
#include <utility>

#include "server/route/shard_router.h"

namespace locator {

void GridCollector::Start(const ShardTopology* topology, size_t shard,
                          std::shared_ptr<grpc::ClientContext> context,
                          const v1::GridRequest* request, uint64_t max_cells,
                          v1::GridResponse* whole,
                          std::function<void(grpc::Status)> finish) {
  auto* collector = new GridCollector(topology, shard, std::move(context),
                                      max_cells, whole, std::move(finish));
  topology->async(shard)->Grid(collector->context_.get(), request, collector);
  collector->StartRead(&collector->message_);
  collector->StartCall();
}

GridCollector::GridCollector(const ShardTopology* topology, size_t shard,
                             std::shared_ptr<grpc::ClientContext> context,
                             uint64_t max_cells, v1::GridResponse* whole,
                             std::function<void(grpc::Status)> finish)
    : topology_(topology),
      shard_(shard),
      context_(std::move(context)),
      max_cells_(max_cells),
      whole_(whole),
      finish_(std::move(finish)) {}

void GridCollector::OnReadDone(bool ok) {
  // Not ok: the shard's stream ended; OnDone(status) follows.
  if (!ok) return;
  refusal_ = Take();
  if (refusal_) {
    context_->TryCancel();
    return;
  }
  StartRead(&message_);
}

grpc::Status GridCollector::Broken(const std::string& what) const {
  return FromShard(
      *topology_, shard_,
      grpc::Status(grpc::StatusCode::INTERNAL, "its grid stream " + what));
}

std::optional<grpc::Status> GridCollector::Take() {
  if (message_.has_header() == header_seen_) {
    return Broken("does not start with its header, once");
  }
  if (message_.has_header()) {
    header_seen_ = true;
    const v1::GridHeader& header = message_.header();
    const uint64_t cells = uint64_t{header.width()} * header.height();
    // A height past the limit is refused too: rows are counted one by one
    // even when they have no cells.
    if (cells > max_cells_ || header.height() > max_cells_) {
      return grpc::Status(
          grpc::StatusCode::RESOURCE_EXHAUSTED,
          "the grid has " + std::to_string(header.width()) + " x " +
              std::to_string(header.height()) + " = " + std::to_string(cells) +
              " cells, past the limit of " + std::to_string(max_cells_) +
              " cells of one JSON answer (--http-max-grid-cells)");
    }
    *whole_->mutable_header() = header;
    whole_->mutable_values()->Resize(static_cast<int>(cells), 0.0);
    row_seen_.assign(header.height(), false);
  }
  const uint64_t width = whole_->header().width();
  const uint64_t height = whole_->header().height();
  if (uint64_t{message_.first_row()} + message_.rows() > height ||
      static_cast<uint64_t>(message_.values_size()) !=
          uint64_t{message_.rows()} * width) {
    return Broken("sends rows its header does not have");
  }
  for (uint32_t r = message_.first_row();
       r < message_.first_row() + message_.rows(); ++r) {
    if (row_seen_[r]) {
      return Broken("sends row " + std::to_string(r) + " twice");
    }
    row_seen_[r] = true;
  }
  rows_seen_ += message_.rows();
  std::copy(message_.values().begin(), message_.values().end(),
            whole_->mutable_values()->begin() + message_.first_row() * width);
  return std::nullopt;
}

void GridCollector::OnDone(const grpc::Status& status) {
  grpc::Status outcome =
      refusal_ ? *refusal_ : FromShard(*topology_, shard_, status);
  if (outcome.ok() &&
      (!header_seen_ || rows_seen_ != whole_->header().height())) {
    outcome = Broken("ends short of its header's rows");
  }
  if (outcome.ok()) {
    whole_->set_first_row(0);
    whole_->set_rows(whole_->header().height());
  }
  finish_(std::move(outcome));
  delete this;
}

}  // namespace locator
