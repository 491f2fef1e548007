// Validation of flag values typed as text: whole numbers in a range, seconds,
// byte sizes. Every error is InvalidArgument "--flag 'text': problem", so a
// bad value fails at startup with a message naming the flag. Shared by the
// flag groups of server_config.cc and security_config.cc.
//
// Thread-safety: free functions over plain values.

#ifndef LOCATOR_SERVER_FLAG_PARSING_H_
#define LOCATOR_SERVER_FLAG_PARSING_H_

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "locator/status.h"

namespace locator {

// InvalidArgument "--<flag> '<text>': <problem>".
Status FlagError(std::string_view flag, std::string_view text,
                 std::string_view problem);

// Parses a whole number in [min, max].
Status ParseCount(std::string_view flag, std::string_view text, uint64_t min,
                  uint64_t max, uint64_t* out);

// ParseCount into any integer type that holds [min, max].
template <typename T>
Status ParseCountAs(std::string_view flag, std::string_view text, uint64_t min,
                    uint64_t max, T* out) {
  uint64_t value = 0;
  Status status = ParseCount(flag, text, min, max, &value);
  if (status.ok()) *out = static_cast<T>(value);
  return status;
}

// Parses a finite number of seconds >= 0.
Status ParseSeconds(std::string_view flag, std::string_view text, double* out);

// Parses a byte size (B, KiB, MiB, GiB suffix) in [min, max].
Status ParseByteFlag(std::string_view flag, std::string_view text, uint64_t min,
                     uint64_t max, size_t* out);

}  // namespace locator

#endif  // LOCATOR_SERVER_FLAG_PARSING_H_
