// JsonWriter: builds one JSON text in a string, with commas placed for the
// caller. The project's one writer of JSON that is not a proto message (the
// HTTP side's errors, grids and status pages, locator-load's report); proto
// messages go through protobuf's JSON mapping (common/proto_json.h).
//
// Strings are escaped (control characters, quotes, backslashes, and '<',
// '>', '&' so the text is inert if embedded in HTML); bytes that are not
// valid UTF-8 become U+FFFD. Non-finite numbers are written as null.
//
// Owns the text. Invariant: the caller nests Begin/End calls properly and
// writes a Key() before each value inside an object. Thread-safety: none.

#ifndef LOCATOR_COMMON_JSON_WRITER_H_
#define LOCATOR_COMMON_JSON_WRITER_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace locator {

class JsonWriter {
 public:
  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  // The name of the next member of the current object.
  JsonWriter& Key(std::string_view name);

  JsonWriter& String(std::string_view value);
  // Shortest text that reads back as `value`; null if it is not finite.
  JsonWriter& Number(double value);
  // As protobuf's JSON mapping writes a double: Number(), but the strings
  // "NaN", "Infinity" and "-Infinity" where it is not finite.
  JsonWriter& ProtoNumber(double value);
  JsonWriter& Integer(uint64_t value);
  JsonWriter& Bool(bool value);
  JsonWriter& Null();
  // A value that is already JSON text (not checked).
  JsonWriter& Raw(std::string_view json);

  // Room for `bytes` of text in all, so that a large text grows once.
  void Reserve(size_t bytes) { text_.reserve(bytes); }
  // The text written so far.
  const std::string& text() const { return text_; }
  // Moves the text out; the writer is empty afterwards.
  std::string TakeText() {
    std::string text = std::move(text_);
    text_.clear();
    empty_.clear();
    after_key_ = false;
    return text;
  }

 private:
  // Writes the comma that separates a value from its predecessor.
  void BeforeValue();
  // Starts or ends an object or array.
  void Open(char bracket);
  void Close(char bracket);
  void AppendEscaped(std::string_view value);

  std::string text_;
  // One entry per open object or array: whether it has no element yet.
  std::vector<bool> empty_;
  bool after_key_ = false;
};

}  // namespace locator

#endif  // LOCATOR_COMMON_JSON_WRITER_H_
