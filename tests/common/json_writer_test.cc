#include "common/json_writer.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "tests/server/http/json_value.h"

namespace locator {
namespace {

using test::JsonValue;
using test::ParseJson;

TEST(JsonWriterTest, NestsAndSeparatesValues) {
  JsonWriter json;
  json.BeginObject()
      .Key("a")
      .Integer(1)
      .Key("b")
      .BeginArray()
      .Bool(true)
      .Null()
      .BeginObject()
      .EndObject()
      .BeginArray()
      .EndArray()
      .EndArray()
      .Key("c")
      .String("x")
      .EndObject();
  EXPECT_EQ(json.text(), R"({"a":1,"b":[true,null,{},[]],"c":"x"})");
}

TEST(JsonWriterTest, NonFiniteNumbersAreNullAndFiniteOnesRoundTrip) {
  const double values[] = {0.1, -2.5e-300, 1e308, 123456789.125, 3};
  JsonWriter json;
  json.BeginArray()
      .Number(std::numeric_limits<double>::quiet_NaN())
      .Number(std::numeric_limits<double>::infinity())
      .Number(-std::numeric_limits<double>::infinity());
  for (double v : values) json.Number(v);
  json.EndArray();
  JsonValue parsed;
  ASSERT_TRUE(ParseJson(json.text(), &parsed).ok()) << json.text();
  const auto& array = parsed.array();
  ASSERT_EQ(array.size(), 8u);
  for (size_t i = 0; i < 3; ++i) EXPECT_TRUE(array[i].is_null());
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(array[3 + i].number(), values[i]);
  EXPECT_EQ(json.text().substr(json.text().size() - 3), ",3]");
}

TEST(JsonWriterTest, EscapesStringsAndKeys) {
  using std::string_literals::operator""s;
  const std::string value = "q\" b\\ nl\n tab\t nul\0 </script>&"s;
  JsonWriter json;
  json.BeginObject().Key("k\"ey").String(value).EndObject();
  EXPECT_EQ(json.text(), R"({"k\"ey":"q\" b\\ nl\u000a tab\u0009 nul\u0000 )"
                         R"(\u003c/script\u003e\u0026"})");
  JsonValue parsed;
  ASSERT_TRUE(ParseJson(json.text(), &parsed).ok());
  EXPECT_EQ(parsed["k\"ey"].string(), value);
}

TEST(JsonWriterTest, InvalidUtf8BecomesReplacementCharacters) {
  JsonWriter json;
  // Valid: é (2 bytes), € (3), 😀 (4). Invalid: a lone continuation byte,
  // a truncated sequence, an overlong '/', a surrogate.
  json.String(
      "\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80|\x80|\xE2\x82|\xC0\xAF|"
      "\xED\xA0\x80");
  JsonValue parsed;
  ASSERT_TRUE(ParseJson(json.text(), &parsed).ok()) << json.text();
  EXPECT_EQ(parsed.string(),
            "\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80|\xEF\xBF\xBD|"
            "\xEF\xBF\xBD\xEF\xBF\xBD|\xEF\xBF\xBD\xEF\xBF\xBD|"
            "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");
}

}  // namespace
}  // namespace locator
