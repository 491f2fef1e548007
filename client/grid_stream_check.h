// GridStreamCheck: checks a Grid stream message by message as it arrives,
// so that a server that breaks the contract of locator.v1.GridResponse
// gives an error rather than a crash or a wrong raster: the first message,
// and only the first, carries a header with a non-empty size; every
// message's rows lie inside the raster, come once (in any order), and carry
// rows x width values; at the end every row has come.
//
// Thread-safety: none; one thread reads the stream.

#ifndef LOCATOR_CLIENT_GRID_STREAM_CHECK_H_
#define LOCATOR_CLIENT_GRID_STREAM_CHECK_H_

#include <cstdint>
#include <vector>

#include "locator/status.h"
#include "locator/v1/locator.pb.h"

namespace locator {

class GridStreamCheck {
 public:
  // Checks the next message of the stream. Internal, beginning with "the
  // server's grid stream: ", naming what is wrong.
  Status Check(const v1::GridResponse& message);
  // Internal unless the header and every row of the raster have come.
  Status CheckComplete() const;

  // Whether the header has come; header() is valid once it has.
  bool has_header() const { return has_header_; }
  const v1::GridHeader& header() const { return header_; }

 private:
  bool has_header_ = false;
  v1::GridHeader header_;
  std::vector<bool> row_received_;  // one per row, once the header has come
  uint64_t rows_received_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_GRID_STREAM_CHECK_H_
