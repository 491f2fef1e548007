// StrCat: joins string pieces with one allocation.
//
// Beyond speed, it keeps "literal" + std::string chains out of the client's
// text formatting: GCC 12 misreports those as overlapping memcpy
// (-Wrestrict, GCC bug 105329).
//
// Thread-safety: a pure function.

#ifndef LOCATOR_COMMON_STR_CAT_H_
#define LOCATOR_COMMON_STR_CAT_H_

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace locator {

inline std::string StrCat(std::initializer_list<std::string_view> pieces) {
  size_t size = 0;
  for (std::string_view piece : pieces) size += piece.size();
  std::string joined;
  joined.reserve(size);
  for (std::string_view piece : pieces) joined.append(piece);
  return joined;
}

}  // namespace locator

#endif  // LOCATOR_COMMON_STR_CAT_H_
