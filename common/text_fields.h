// Reading number text: how a line splits into fields and how a field reads
// as a double. The core's dataset parsers (CSV/XYZ, .node, .poly, .ele,
// WKT) and the client's query points reader share these, so that a file
// reads alike as a dataset and as queries.
//
// A line's fields are separated by whitespace and/or one comma; '#' starts a
// comment; a line of blanks and comments has no content. Two commas in a row
// (or a leading or trailing comma) make an empty field, which a reader
// reports rather than silently shifting the columns.
//
// Thread-safety: plain functions, and a reader owned by one parse.

#ifndef LOCATOR_COMMON_TEXT_FIELDS_H_
#define LOCATOR_COMMON_TEXT_FIELDS_H_

#include <array>
#include <cstddef>
#include <string_view>

namespace locator {

// The fields of one content line.
struct TextFields {
  // Enough for "index x y value" of a .node line; later ones are only counted.
  static constexpr size_t kStored = 4;
  static constexpr size_t kNoEmpty = static_cast<size_t>(-1);

  std::array<std::string_view, kStored> field;
  size_t count = 0;
  // The index the first empty field would have among the fields (kNoEmpty
  // if there is none): a field before it is field[i], one at or after it
  // is shifted.
  size_t first_empty = kNoEmpty;

  bool has_empty() const { return first_empty != kNoEmpty; }
};

// Splits `line` (without its '\n') into *f; false, leaving *f unspecified,
// when it has no content.
bool SplitFields(std::string_view line, TextFields* f);

// Iterates over the content lines of a whole text. Line numbers count every
// line, so errors point at the line the user sees in an editor.
class TextFieldReader {
 public:
  explicit TextFieldReader(std::string_view text) : text_(text) {}

  // Splits the next content line into *f; false at the end of the text.
  bool Next(TextFields* f);

  // 1-based number of the line last returned (after the end: the last line).
  size_t line_number() const { return line_number_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_number_ = 0;
};

enum class NumberKind { kFinite, kNonFinite, kNotANumber };

// Reads all of `s` as a double ("1e3", "+2", "-0.5", "nan", "inf"; an
// overflow reads as infinity, an underflow as the nearest tiny value) and
// says whether it is a finite number, a non-finite one or not a number.
NumberKind ParseNumber(std::string_view s, double* value);

// Whether all of `s` is a number, finite or not (ParseNumber).
inline bool ParseDouble(std::string_view s, double* value) {
  return ParseNumber(s, value) != NumberKind::kNotANumber;
}

}  // namespace locator

#endif  // LOCATOR_COMMON_TEXT_FIELDS_H_
