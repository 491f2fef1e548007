// Doubles in messages: the shortest text that reads back as the same
// double ("1e+160", "0.1", "1.7976931348623157e+308"), never the hundreds of
// digits std::to_string prints for large or tiny values.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_NUMBER_TEXT_H_
#define LOCATOR_CORE_NUMBER_TEXT_H_

#include <charconv>
#include <string>
#include <system_error>

#include "common/geometry.h"
#include "common/str_cat.h"

namespace locator {

// v as the shortest text that round-trips ("nan", "inf" and "-inf" too).
inline std::string NumberText(double v) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof(text), v);
  return std::string(text, error == std::errc() ? end : text);
}

// "(x, y)".
inline std::string PointText(const Point2& p) {
  return StrCat({"(", NumberText(p.x), ", ", NumberText(p.y), ")"});
}

}  // namespace locator

#endif  // LOCATOR_CORE_NUMBER_TEXT_H_
