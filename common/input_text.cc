#include "common/input_text.h"

#include <charconv>

namespace locator {
namespace {

// The longest prefix of `text` of at most `max_bytes` bytes that does not
// end inside a UTF-8 character.
std::string_view Utf8Prefix(std::string_view text, size_t max_bytes) {
  if (text.size() <= max_bytes) return text;
  size_t end = max_bytes;
  // Continuation bytes are 10xxxxxx: back off to the character's first byte.
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) {
    --end;
  }
  return text.substr(0, end);
}

void AppendShown(std::string_view text, std::string* out) {
  constexpr char kHex[] = "0123456789abcdef";
  for (const char c : text) {
    if (IsControlByte(c)) {
      const auto byte = static_cast<unsigned char>(c);
      out->append("\\x");
      out->push_back(kHex[byte >> 4]);
      out->push_back(kHex[byte & 0xf]);
    } else {
      out->push_back(c);
    }
  }
}

}  // namespace

std::string QuotedInput(std::string_view text) {
  const std::string_view shown = Utf8Prefix(text, kQuotedInputBytes);
  std::string quoted = "'";
  AppendShown(shown, &quoted);
  if (shown.size() == text.size()) {
    quoted.push_back('\'');
  } else {
    quoted.append("...' (");
    quoted.append(std::to_string(text.size()));
    quoted.append(" bytes)");
  }
  return quoted;
}

std::string NumberText(double value) {
  // The shortest round-trip form of a double has at most 24 characters
  // ("-2.2250738585072014e-308"), so this buffer always holds it.
  char buffer[32];
  const std::to_chars_result written =
      std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, written.ptr);
}

std::string PointText(const Point2& p) {
  return "(" + NumberText(p.x) + ", " + NumberText(p.y) + ")";
}

std::string TruncatedMessage(std::string_view message, size_t max_bytes) {
  if (message.size() <= max_bytes) return std::string(message);
  std::string cut(Utf8Prefix(message, max_bytes - 3));
  cut.append("...");
  return cut;
}

}  // namespace locator
