// The state file BinPoints leaves beside its sorted points ("bins.state"):
// what a resumed build needs to use them without binning again. Checked
// by an XXH3 checksum and the key of the source it was made for.
//
// Thread-safety: free functions.

#ifndef LOCATOR_CORE_TILESET_BINS_STATE_H_
#define LOCATOR_CORE_TILESET_BINS_STATE_H_

#include <cstdint>
#include <string>

#include "locator/status.h"
#include "server/core/tileset/point_bins.h"

namespace locator {

// Writes `binned`'s state for `key` to dir/bins.state, atomically. IOError
// naming the step that failed.
[[nodiscard]] Status SaveBinsState(const std::string& dir, uint64_t key,
                                   const BinnedPoints& binned);

// Reads dir/bins.state into *out. NotFound if there is none, or it is
// damaged or made for another key; then the points are binned again.
[[nodiscard]] Status LoadBinsState(const std::string& dir, uint64_t key,
                                   BinnedPoints* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_BINS_STATE_H_
