#include "common/flags/byte_size.h"

#include <array>
#include <charconv>
#include <limits>
#include <string>
#include <utility>

namespace locator {

Status ParseByteSize(std::string_view text, size_t* bytes) {
  static constexpr std::array<std::pair<std::string_view, size_t>, 10> kUnits =
      {{{"", 1},
        {"B", 1},
        {"K", size_t{1} << 10},
        {"KiB", size_t{1} << 10},
        {"KB", 1000},
        {"M", size_t{1} << 20},
        {"MiB", size_t{1} << 20},
        {"MB", 1000 * 1000},
        {"G", size_t{1} << 30},
        {"GiB", size_t{1} << 30}}};
  const auto bad = [&] {
    return Status::InvalidArgument(
        "bad byte size '" + std::string(text) +
        "' (expected a whole number with an optional unit: B, KiB, MiB, "
        "GiB, KB, MB)");
  };
  size_t value = 0;
  const auto [rest, ec] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || rest == text.data()) return bad();
  const std::string_view unit(rest, text.data() + text.size() - rest);
  for (const auto& [name, scale] : kUnits) {
    if (unit != name) continue;
    if (value > std::numeric_limits<size_t>::max() / scale) return bad();
    *bytes = value * scale;
    return Status::OK();
  }
  return bad();
}

}  // namespace locator
