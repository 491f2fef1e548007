#include "client/grid_stream_check.h"

#include <string>

namespace locator {
namespace {

Status Broken(const std::string& what) {
  return Status::Internal("the server's grid stream: " + what);
}

}  // namespace

Status GridStreamCheck::Check(const v1::GridResponse& message) {
  if (message.has_header()) {
    if (has_header_) return Broken("a second header");
    header_ = message.header();
    if (header_.width() == 0 || header_.height() == 0) {
      return Broken("the header's raster is " +
                    std::to_string(header_.width()) + " x " +
                    std::to_string(header_.height()));
    }
    has_header_ = true;
    row_received_.assign(header_.height(), false);
  } else if (!has_header_) {
    return Broken("rows before the header");
  }
  const uint32_t first = message.first_row(), rows = message.rows();
  if (first > header_.height() || rows > header_.height() - first) {
    return Broken("rows " + std::to_string(first) + " + " +
                  std::to_string(rows) + " outside the raster's " +
                  std::to_string(header_.height()));
  }
  if (static_cast<uint64_t>(message.values_size()) !=
      uint64_t{rows} * header_.width()) {
    return Broken(std::to_string(message.values_size()) + " values for " +
                  std::to_string(rows) + " rows of " +
                  std::to_string(header_.width()));
  }
  for (uint32_t row = first; row < first + rows; ++row) {
    if (row_received_[row]) {
      return Broken("row " + std::to_string(row) + " twice");
    }
    row_received_[row] = true;
  }
  rows_received_ += rows;
  return Status::OK();
}

Status GridStreamCheck::CheckComplete() const {
  if (!has_header_) return Broken("no header");
  if (rows_received_ == header_.height()) return Status::OK();
  return Broken("ended after " + std::to_string(rows_received_) + " of " +
                std::to_string(header_.height()) + " rows");
}

}  // namespace locator
