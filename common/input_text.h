// How a message shows what a client (or a file) gave: a string quoted and
// cut to a short prefix, a number in its shortest round-trip form.
//
// Every error message that echoes request text goes through these, so that
// its size stays bounded whatever the request (a gRPC status travels in a
// header of a few KiB, and a message that overflows it reaches the client as
// an unrelated error), and a number reads as it was typed: 1e-300, not
// "0.000000", and 1e+302, not 303 digits.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_COMMON_INPUT_TEXT_H_
#define LOCATOR_COMMON_INPUT_TEXT_H_

#include <cstddef>
#include <string>
#include <string_view>

#include "locator/geometry.h"

namespace locator {

// The most bytes of a string QuotedInput() shows.
inline constexpr size_t kQuotedInputBytes = 80;

// Whether `c` is an ASCII control character (below 0x20, or DEL), which a
// message of one line must not hold.
inline bool IsControlByte(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return byte < 0x20 || byte == 0x7f;
}

// `text` in single quotes. Longer than kQuotedInputBytes: its first bytes
// (never half a UTF-8 character), "...", and its size, as
// 'abc...' (10485760 bytes). Control characters are shown as \xNN, so that
// a message stays one line.
std::string QuotedInput(std::string_view text);

// The shortest text that reads back as exactly `value` ("0.1", "1e-300",
// "-1.7976931348623157e+308", "inf", "nan").
std::string NumberText(double value);

// "(x, y)", each coordinate as NumberText() shows it.
std::string PointText(const Point2& p);

// `message` if it has at most `max_bytes` bytes; otherwise its first bytes
// (never half a UTF-8 character) followed by "...", `max_bytes` in all
// (`max_bytes` >= 3).
std::string TruncatedMessage(std::string_view message, size_t max_bytes);

// The longest status message sent, in bytes; longer ones end in "...". Even
// percent-encoded (3 bytes for each byte that is not printable ASCII) it
// fits gRPC's default 8 KiB header limit with room for the other headers.
inline constexpr size_t kMaxStatusMessageBytes = 1024;

}  // namespace locator

#endif  // LOCATOR_COMMON_INPUT_TEXT_H_
