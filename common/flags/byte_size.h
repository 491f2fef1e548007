// ParseByteSize: "65536", "64KiB", "3MiB", "1GiB" (also KB/MB/GB as
// powers of 1000, and a bare "K"/"M"/"G" as binary) into bytes. The value
// of the byte-size flags (flag::Bytes, flag_value.h).
//
// Thread-safety: a free function over plain values.

#ifndef LOCATOR_COMMON_FLAGS_BYTE_SIZE_H_
#define LOCATOR_COMMON_FLAGS_BYTE_SIZE_H_

#include <cstddef>
#include <string_view>

#include "locator/status.h"

namespace locator {

// InvalidArgument naming the text for anything else, or on overflow.
Status ParseByteSize(std::string_view text, size_t* bytes);

}  // namespace locator

#endif  // LOCATOR_COMMON_FLAGS_BYTE_SIZE_H_
