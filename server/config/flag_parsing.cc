#include "server/config/flag_parsing.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

#include "server/core/dataset/byte_size.h"

namespace locator {

Status FlagError(std::string_view flag, std::string_view text,
                 std::string_view problem) {
  std::ostringstream msg;
  msg << "--" << flag << " '" << text << "': " << problem;
  return Status::InvalidArgument(msg.str());
}

Status ParseCount(std::string_view flag, std::string_view text, uint64_t min,
                  uint64_t max, uint64_t* out) {
  uint64_t value = 0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() ||
      text.empty()) {
    return FlagError(flag, text, "not a whole number");
  }
  if (value < min || value > max) {
    std::ostringstream range;
    range << "must be between " << min << " and " << max;
    return FlagError(flag, text, range.str());
  }
  *out = value;
  return Status::OK();
}

Status ParseSeconds(std::string_view flag, std::string_view text, double* out) {
  double value = 0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value) || value < 0) {
    return FlagError(flag, text, "not a number of seconds >= 0");
  }
  *out = value;
  return Status::OK();
}

Status ParseByteFlag(std::string_view flag, std::string_view text, uint64_t min,
                     uint64_t max, size_t* out) {
  size_t bytes = 0;
  if (Status status = ParseByteSize(text, &bytes); !status.ok()) {
    // The message already quotes the text.
    return Status::InvalidArgument("--" + std::string(flag) + ": " +
                                   status.message());
  }
  if (bytes < min || bytes > max) {
    std::ostringstream range;
    range << "must be between " << min << " and " << max << " bytes";
    return FlagError(flag, text, range.str());
  }
  *out = bytes;
  return Status::OK();
}

}  // namespace locator
