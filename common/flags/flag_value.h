// FlagValue: how the words of one command-line flag become a typed value,
// and the makers of the kinds every program uses (flag::Switch, flag::Text,
// flag::Count, flag::Seconds, flag::Number, flag::Bytes, flag::Choice,
// flag::Repeated, flag::Words, flag::Parsed, and the comma-separated lists
// flag::Counts, flag::Numbers, flag::Texts). A FlagSet (flag_set.h) holds
// one per flag and calls its `parse` for each occurrence on the line.
//
// A maker binds the value to its destination, whose value at that moment
// is the default: it is kept when the flag is not given and shown by
// --help. A `parse` that refuses returns InvalidArgument whose message is
// the problem with the accepted form, phrased to follow "--flag 'text': "
// (e.g. "must be a whole number from 1 to 256"); FlagSet adds that prefix,
// so every program words its flag errors alike (FlagError).
//
// Ownership: a FlagValue points at its destination, which must outlive the
// FlagSet's Parse. Thread-safety: plain values; parse from one thread.

#ifndef LOCATOR_COMMON_FLAGS_FLAG_VALUE_H_
#define LOCATOR_COMMON_FLAGS_FLAG_VALUE_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "locator/status.h"

namespace locator {

// InvalidArgument "--<flag> '<text>': <problem>": the one wording of a bad
// flag value, for the checks a program makes after parsing too.
Status FlagError(std::string_view flag, std::string_view text,
                 std::string_view problem);

struct FlagValue {
  // Words the flag takes: 0 for a switch, otherwise exactly this many, from
  // "--flag=first" and the words after it, or from the words after --flag.
  size_t words = 1;
  // Whether the flag may be given more than once; otherwise a second
  // occurrence is an error.
  bool repeatable = false;
  // The value's shape in --help: "N", "SECONDS", "SIZE", "a|b|c", ...
  std::string shape;
  // The default as --help shows it; empty: no default is shown.
  std::string default_text;
  // Stores the words (`words` of them) in the destination, or returns
  // InvalidArgument saying the problem (see above) and stores nothing.
  std::function<Status(const std::vector<std::string>& words)> parse;

  // The same value with another shape or default shown by --help.
  FlagValue Shape(std::string text) && {
    shape = std::move(text);
    return std::move(*this);
  }
  FlagValue Default(std::string text) && {
    default_text = std::move(text);
    return std::move(*this);
  }
};

namespace flag {

// --flag sets *out to true; it takes no value.
FlagValue Switch(bool* out);

// Any text, the empty text too. Shape "TEXT".
FlagValue Text(std::string* out);

// A whole number in [min, max], written through `store`; `current` is the
// default. Shape "N". The typed Count below is what programs call.
FlagValue CountInto(uint64_t min, uint64_t max, uint64_t current,
                    std::function<void(uint64_t)> store);

// A whole number in [min, max] into any unsigned or signed integer type
// that holds max (a negative default is not shown).
template <typename T>
FlagValue Count(T* out, uint64_t min, uint64_t max) {
  static_assert(std::is_integral_v<T>);
  return CountInto(min, max, *out < 0 ? 0 : static_cast<uint64_t>(*out),
                   [out](uint64_t value) { *out = static_cast<T>(value); });
}

// The largest Count of a type, for flags bounded only by it (--help and
// errors then say ">= min").
template <typename T>
constexpr uint64_t kMaxOf =
    static_cast<uint64_t>(std::numeric_limits<T>::max());

// A finite number >= min (> min when `above`). Shape "X".
FlagValue Number(double* out, double min, bool above = false);

// Number, of seconds. Shape "SECONDS".
FlagValue Seconds(double* out, double min = 0, bool above = false);

// A byte size (ParseByteSize: 65536, 64KiB, 3MiB, 1GiB, ...) in [min, max],
// through `store`. Shape "SIZE". The typed Bytes below is what programs
// call.
FlagValue BytesInto(uint64_t min, uint64_t max, uint64_t current,
                    std::function<void(uint64_t)> store);

template <typename T>
FlagValue Bytes(T* out, uint64_t min, uint64_t max) {
  static_assert(std::is_unsigned_v<T>);
  return BytesInto(min, max, *out,
                   [out](uint64_t value) { *out = static_cast<T>(value); });
}

// A comma-separated list ("1000,20000"), each item read by `element`
// (which stores through its own function): `begin` runs before the first
// item, `commit` after the last when all were accepted. The typed lists
// below are what programs call; they replace their default.
FlagValue CommaList(FlagValue element, std::function<void()> begin,
                    std::function<void()> commit, std::string default_text);

// "a,b,c" of a list's default.
template <typename T>
std::string JoinList(const std::vector<T>& items) {
  std::ostringstream text;
  for (size_t i = 0; i < items.size(); ++i) text << (i ? "," : "") << items[i];
  return text.str();
}

// Whole numbers in [min, max], comma-separated. Shape "N,N,...".
template <typename T>
FlagValue Counts(std::vector<T>* out, uint64_t min, uint64_t max) {
  auto parsed = std::make_shared<std::vector<T>>();
  return CommaList(
      CountInto(min, max, 0,
                [parsed](uint64_t v) { parsed->push_back(static_cast<T>(v)); }),
      [parsed] { parsed->clear(); }, [parsed, out] { *out = *parsed; },
      JoinList(*out));
}

// A finite number >= min (> min when `above`), through `store`.
FlagValue NumberInto(double min, bool above, std::function<void(double)> store);

// Numbers as Number takes them, comma-separated. Shape "X,X,...".
inline FlagValue Numbers(std::vector<double>* out, double min,
                         bool above = false) {
  auto parsed = std::make_shared<std::vector<double>>();
  return CommaList(
      NumberInto(min, above, [parsed](double v) { parsed->push_back(v); }),
      [parsed] { parsed->clear(); }, [parsed, out] { *out = *parsed; },
      JoinList(*out));
}

// Non-empty words, comma-separated. Shape "WORD,WORD,...".
FlagValue Texts(std::vector<std::string>* out);

// One word of `choices` (word, value), into *out. Shape "a|b|c".
FlagValue ChoiceInto(std::vector<std::string> words, size_t current,
                     std::function<void(size_t index)> store);

template <typename T>
FlagValue Choice(T* out, std::vector<std::pair<std::string, T>> choices) {
  std::vector<std::string> words;
  size_t current = choices.size();
  for (size_t i = 0; i < choices.size(); ++i) {
    words.push_back(choices[i].first);
    if (choices[i].second == *out && current == choices.size()) current = i;
  }
  return ChoiceInto(std::move(words), current,
                    [out, values = std::move(choices)](size_t index) {
                      *out = values[index].second;
                    });
}

// One of `words`, kept as the word.
FlagValue Choice(std::string* out, std::vector<std::string> words);

// Repeatable: each occurrence appends its text. The destination's contents
// are the default, replaced by the first occurrence. Shape "TEXT".
FlagValue Repeated(std::vector<std::string>* out);

// Exactly `count` words, kept as typed (--te XMIN YMIN XMAX YMAX); the words
// may start with '-' ("-10"). The caller gives the shape.
FlagValue Words(std::vector<std::string>* out, size_t count);

// Text that `parse` reads into its own destinations (HOST:PORT into a host
// and a port, a polyline into points); it returns the problem otherwise.
// Shape "TEXT"; no default shown unless given by Default().
FlagValue Parsed(std::function<Status(std::string_view text)> parse);

}  // namespace flag
}  // namespace locator

#endif  // LOCATOR_COMMON_FLAGS_FLAG_VALUE_H_
