#include "common/text_fields.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

namespace locator {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

bool SplitFields(std::string_view line, TextFields* f) {
  line = line.substr(0, line.find('#'));
  size_t i = 0;
  while (i < line.size() && IsSpace(line[i])) ++i;
  if (i == line.size()) return false;
  f->count = 0;
  f->first_empty = TextFields::kNoEmpty;
  const auto empty_at = [f](size_t index) {
    if (!f->has_empty()) f->first_empty = index;
  };
  while (i < line.size()) {
    const size_t start = i;
    while (i < line.size() && !IsSpace(line[i]) && line[i] != ',') ++i;
    if (f->count < TextFields::kStored) {
      f->field[f->count] = line.substr(start, i - start);
    }
    if (i == start) empty_at(f->count);  // only a leading comma does this
    ++f->count;
    int commas = 0;
    while (i < line.size() && (IsSpace(line[i]) || line[i] == ',')) {
      commas += line[i++] == ',';
    }
    if (commas > 1 || (commas == 1 && i == line.size())) empty_at(f->count);
  }
  return true;
}

bool TextFieldReader::Next(TextFields* f) {
  while (pos_ < text_.size()) {
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    const std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_number_;
    if (SplitFields(line, f)) return true;
  }
  return false;
}

NumberKind ParseNumber(std::string_view s, double* value) {
  // from_chars rejects a leading '+', which other tools do write.
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, *value);
  if (ptr != end || ec == std::errc::invalid_argument) {
    return NumberKind::kNotANumber;
  }
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports overflow and underflow alike and leaves *value
    // untouched; strtod tells them apart (an underflow is a fine ~0). This is
    // the rare path, so the copy does not matter.
    *value = std::strtod(std::string(s).c_str(), nullptr);
  }
  return std::isfinite(*value) ? NumberKind::kFinite : NumberKind::kNonFinite;
}

}  // namespace locator
