// Helpers shared by the dataset text parsers (CSV/XYZ, .node, .poly):
// "file:line: what" errors over the line and number reading of
// common/text_fields.h. Internal to server/core's dataset loading.
//
// Thread-safety: plain functions and a reader owned by one parse.

#ifndef LOCATOR_CORE_DATASET_TEXT_H_
#define LOCATOR_CORE_DATASET_TEXT_H_

#include <algorithm>
#include <array>
#include <charconv>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

#include "common/status_macros.h"
#include "common/text_fields.h"
#include "locator/dataset_sources.h"
#include "locator/status.h"

namespace locator::dataset_text {

// Concatenates strings and integers, for messages.
template <typename... Parts>
inline std::string Cat(const Parts&... parts) {
  std::string out;
  const auto append = [&out](const auto& part) {
    if constexpr (std::is_integral_v<std::decay_t<decltype(part)>>) {
      out += std::to_string(part);
    } else {
      out += part;
    }
  };
  (append(parts), ...);
  return out;
}

inline std::string Quoted(std::string_view s) { return Cat("'", s, "'"); }

// A position in the input, for "file:line: what" messages.
struct Where {
  std::string_view file;
  size_t line;

  std::string Prefix() const { return Cat(file, ":", line); }
  Status Error(std::string_view what) const {
    return Status::InvalidArgument(Cat(Prefix(), ": ", what));
  }
};

inline Status EmptyDataset(std::string_view file) {
  return Status::InvalidArgument(Cat(file, ": empty dataset (no points)"));
}

// `where` is "file:line" or a generator spec.
inline Status TooManyPoints(std::string_view where, size_t limit) {
  return Status::ResourceExhausted(
      Cat(where, ": more than ", limit, " points (max_points limit)"));
}

// Parses a finite double; `noun` names the field in the error message.
inline Status ParseFinite(std::string_view s, std::string_view noun,
                          const Where& where, double* value) {
  const NumberKind kind = ParseNumber(s, value);
  if (kind == NumberKind::kFinite) return Status::OK();
  return where.Error(kind == NumberKind::kNonFinite
                         ? Cat("non-finite ", noun, " ", Quoted(s))
                         : Cat(Quoted(s), " is not a number"));
}

template <typename Int>
inline bool ParseInteger(std::string_view s, Int* value) {
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, *value);
  return ec == std::errc() && ptr == end && !s.empty();
}

// Appends the point in fields [first, first + 1] of `f` and, if
// `with_value`, the value in field first + 2.
inline Status ParsePoint(const TextFields& f, size_t first, bool with_value,
                         const Where& where, Dataset* ds) {
  std::array<double, 3> v;
  const size_t n = with_value ? 3 : 2;
  for (size_t i = 0; i < n; ++i) {
    RETURN_IF_ERROR(ParseFinite(f.field[first + i],
                                i < 2 ? "coordinate" : "value", where, &v[i]));
  }
  ds->points.push_back({v[0], v[1]});
  if (with_value) ds->values.push_back(v[2]);
  return Status::OK();
}

inline size_t ReserveEstimate(std::string_view text, size_t at_most) {
  return std::min<size_t>(std::count(text.begin(), text.end(), '\n') + 1,
                          at_most);
}

// Where a node section started and how it numbers its points.
struct NodeSection {
  size_t header_line = 0;
  // The index of the first point (0 or 1 in practice); the others follow
  // consecutively. Files that refer to points by index subtract it.
  long long first_index = 0;
};

// Reads a section header "<count> [more fields...]" of at most `max_fields`
// fields; `what` names the expected header in the error.
Status ReadCount(TextFieldReader* reader, std::string_view filename,
                 size_t max_fields, std::string_view what, size_t* count);

// Reads the next content line of a section into *f, with at least
// `min_fields` fields; `what` names the row in errors. *where is its line.
Status ReadRow(TextFieldReader* reader, std::string_view filename,
               size_t min_fields, std::string_view what, TextFields* f,
               Where* where);

// Reads Triangle's node section, a header "<#points> <dim> <#attributes>
// <#markers>" and its points (indices consecutive), into `ds`; the first
// attribute, if any, is the value.
Status ParseNodeSection(TextFieldReader* reader, std::string_view filename,
                        const DatasetLimits& limits, Dataset* ds,
                        NodeSection* section);

}  // namespace locator::dataset_text

#endif  // LOCATOR_CORE_DATASET_TEXT_H_
