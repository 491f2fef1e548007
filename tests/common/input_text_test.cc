#include "common/input_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace locator {
namespace {

TEST(QuotedInputTest, ShortTextIsQuotedWhole) {
  EXPECT_EQ(QuotedInput("EPSG:4326"), "'EPSG:4326'");
  EXPECT_EQ(QuotedInput(""), "''");
  const std::string longest(kQuotedInputBytes, 'a');
  EXPECT_EQ(QuotedInput(longest), "'" + longest + "'");
}

TEST(QuotedInputTest, LongTextShowsItsPrefixAndSize) {
  const std::string crs = "+proj=longlat " + std::string(10 << 20, 'x');
  const std::string quoted = QuotedInput(crs);
  EXPECT_EQ(quoted, "'+proj=longlat " +
                        std::string(kQuotedInputBytes - 14, 'x') + "...' (" +
                        std::to_string(crs.size()) + " bytes)");
}

TEST(QuotedInputTest, NeverCutsAUtf8Character) {
  // "é" is two bytes; 79 ASCII bytes put the 80-byte cut inside it.
  const std::string text =
      std::string(kQuotedInputBytes - 1, 'a') + "\xc3\xa9z";
  EXPECT_EQ(QuotedInput(text),
            "'" + std::string(kQuotedInputBytes - 1, 'a') + "...' (82 bytes)");
}

TEST(QuotedInputTest, ControlCharactersKeepTheMessageOnOneLine) {
  EXPECT_EQ(QuotedInput("a\nb\x7f\t"), "'a\\x0ab\\x7f\\x09'");
}

TEST(NumberTextTest, ShortestRoundTripNeverFixedNotation) {
  EXPECT_EQ(NumberText(1e-300), "1e-300");
  EXPECT_EQ(NumberText(1e302), "1e+302");
  EXPECT_EQ(NumberText(0.1), "0.1");
  EXPECT_EQ(NumberText(2.5), "2.5");
  EXPECT_EQ(NumberText(-0.0), "-0");
  EXPECT_EQ(NumberText(std::numeric_limits<double>::max()),
            "1.7976931348623157e+308");
  EXPECT_EQ(NumberText(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(NumberText(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(NumberText(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(NumberText(std::nan("")), "nan");
  // Reads back exactly.
  const double third = 1.0 / 3;
  EXPECT_EQ(std::stod(NumberText(third)), third);
}

TEST(TruncatedMessageTest, CutsLongMessagesToTheLimit) {
  EXPECT_EQ(TruncatedMessage("short", 10), "short");
  EXPECT_EQ(TruncatedMessage("0123456789", 10), "0123456789");
  EXPECT_EQ(TruncatedMessage("0123456789a", 10), "0123456...");
  // Not inside the two bytes of "é".
  EXPECT_EQ(TruncatedMessage("012345\xc3\xa9xyz", 10), "012345...");
}

}  // namespace
}  // namespace locator
