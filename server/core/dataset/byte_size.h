// ParseByteSize: "65536", "64KiB", "3MiB", "1GiB" (also KB/MB/GB as
// powers of 1000, and a bare "K"/"M"/"G" as binary) into bytes.

#ifndef LOCATOR_CORE_BYTE_SIZE_H_
#define LOCATOR_CORE_BYTE_SIZE_H_

#include <cstddef>
#include <string_view>

#include "locator/status.h"

namespace locator {

// InvalidArgument naming the text for anything else, or on overflow.
Status ParseByteSize(std::string_view text, size_t* bytes);

}  // namespace locator

#endif  // LOCATOR_CORE_BYTE_SIZE_H_
