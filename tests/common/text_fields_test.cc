// The line and number reading the core's dataset parsers and the client's
// points reader share: where fields split, where an empty one sits, and
// what kind of number a field is.

#include "common/text_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace locator {
namespace {

// The stored fields of `line`, or {"<none>"} for a line without content.
std::vector<std::string> Split(std::string_view line, TextFields* f) {
  if (!SplitFields(line, f)) return {"<none>"};
  std::vector<std::string> out;
  for (size_t i = 0; i < f->count && i < TextFields::kStored; ++i) {
    out.emplace_back(f->field[i]);
  }
  return out;
}

using Strings = std::vector<std::string>;

TEST(SplitFieldsTest, SplitsAtWhitespaceAndOneComma) {
  TextFields f;
  EXPECT_EQ(Split("1 2", &f), (Strings{"1", "2"}));
  EXPECT_EQ(Split(" 3 , 4 # comment", &f), (Strings{"3", "4"}));
  EXPECT_EQ(Split("5,6\t7\r", &f), (Strings{"5", "6", "7"}));
  EXPECT_FALSE(f.has_empty());
  EXPECT_EQ(Split("a b c d e f", &f), (Strings{"a", "b", "c", "d"}));
  EXPECT_EQ(f.count, 6u);
}

TEST(SplitFieldsTest, BlankAndCommentLinesHaveNoContent) {
  TextFields f;
  EXPECT_EQ(Split("", &f), (Strings{"<none>"}));
  EXPECT_EQ(Split(" \t\r", &f), (Strings{"<none>"}));
  EXPECT_EQ(Split("  # 1 2", &f), (Strings{"<none>"}));
}

TEST(SplitFieldsTest, NamesWhereTheFirstEmptyFieldSits) {
  TextFields f;
  EXPECT_EQ(Split(",1,2", &f), (Strings{"", "1", "2"}));
  EXPECT_EQ(f.first_empty, 0u);
  EXPECT_EQ(Split("1,,2", &f), (Strings{"1", "2"}));
  EXPECT_EQ(f.first_empty, 1u);
  EXPECT_EQ(Split("1,2,", &f), (Strings{"1", "2"}));
  EXPECT_EQ(f.first_empty, 2u);
  EXPECT_EQ(Split("1,2,t,,,,9", &f), (Strings{"1", "2", "t", "9"}));
  EXPECT_EQ(f.first_empty, 3u);
  EXPECT_TRUE(f.has_empty());
}

TEST(TextFieldReaderTest, CountsEveryLine) {
  TextFieldReader reader("x,y\n\n# c\n1 2\r\n3,4");
  TextFields f;
  std::vector<size_t> lines;
  while (reader.Next(&f)) lines.push_back(reader.line_number());
  EXPECT_EQ(lines, (std::vector<size_t>{1, 4, 5}));
}

TEST(ParseNumberTest, TellsFiniteNonFiniteAndNotANumber) {
  double v = 0;
  EXPECT_EQ(ParseNumber("-1.5e3", &v), NumberKind::kFinite);
  EXPECT_EQ(v, -1500);
  EXPECT_EQ(ParseNumber("+2", &v), NumberKind::kFinite);
  EXPECT_EQ(v, 2);
  EXPECT_EQ(ParseNumber("1e-400", &v), NumberKind::kFinite);
  EXPECT_GE(v, 0);
  EXPECT_LT(v, std::numeric_limits<double>::min());
  EXPECT_EQ(ParseNumber("1e400", &v), NumberKind::kNonFinite);
  EXPECT_EQ(v, std::numeric_limits<double>::infinity());
  EXPECT_EQ(ParseNumber("nan", &v), NumberKind::kNonFinite);
  EXPECT_EQ(ParseNumber("-inf", &v), NumberKind::kNonFinite);
  for (const char* bad : {"", "+", "+-1", "1.5x", "abc", " 1", "1 "}) {
    EXPECT_EQ(ParseNumber(bad, &v), NumberKind::kNotANumber) << bad;
    EXPECT_FALSE(ParseDouble(bad, &v)) << bad;
  }
  EXPECT_TRUE(ParseDouble("inf", &v));
}

}  // namespace
}  // namespace locator
