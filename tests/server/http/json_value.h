// JsonValue: a strict JSON parser (RFC 8259) for tests that check what the
// status API and page produce. Numbers are doubles; objects keep their
// members in a map (duplicate names are an error).
//
// Thread-safety: values are plain data.

#ifndef LOCATOR_TESTS_SERVER_HTTP_JSON_VALUE_H_
#define LOCATOR_TESTS_SERVER_HTTP_JSON_VALUE_H_

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "locator/status.h"

namespace locator::test {

struct JsonValue;
using JsonArray = std::vector<JsonValue>;
using JsonObject = std::map<std::string, JsonValue, std::less<>>;

struct JsonValue {
  std::variant<std::nullptr_t, bool, double, std::string, JsonArray, JsonObject>
      value;

  bool is_null() const { return std::holds_alternative<std::nullptr_t>(value); }
  double number() const { return std::get<double>(value); }
  const std::string& string() const { return std::get<std::string>(value); }
  const JsonArray& array() const { return std::get<JsonArray>(value); }
  const JsonObject& object() const { return std::get<JsonObject>(value); }
  // Member `name` of an object; throws std::out_of_range if absent.
  const JsonValue& operator[](std::string_view name) const;
};

// Parses exactly one JSON text (surrounding whitespace allowed).
// InvalidArgument naming the byte offset otherwise.
Status ParseJson(std::string_view text, JsonValue* out);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_JSON_VALUE_H_
