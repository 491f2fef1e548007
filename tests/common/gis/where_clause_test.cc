// CheckPlainWhereClause: comparisons of fields and literals pass; function
// calls, sub-selects and anything else SQL could do are refused with the
// byte offset where they start.

#include "common/gis/where_clause.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace locator::gis {
namespace {

using ::testing::HasSubstr;

TEST(WhereClauseTest, PlainComparisonsPass) {
  for (const char* where : {
           "id % 15 >= 7",
           "height > 10 AND kind = 'a''b' OR NOT (x <> -1.5e3)",
           "\"odd name\" IS NOT NULL",
           "z BETWEEN 1 AND 2 AND k NOT IN ('a', 'b', 3)",
           "name LIKE 'N%' ESCAPE '\\\\'",
           "a != b AND c <= .5 AND d IS NULL",
           "((((x = 1))))",
           "x / 2 * 3 - +4 = y",
       }) {
    const Status status = CheckPlainWhereClause(where);
    EXPECT_TRUE(status.ok()) << where << ": " << status.ToString();
  }
}

TEST(WhereClauseTest, SqlBeyondComparisonsIsRefusedWhereItStarts) {
  const struct {
    const char* where;
    const char* message;
  } kCases[] = {
      {"(SELECT substr(secret, 1, 1) FROM x.t) = 'a'",
       "at byte 8, expected ')', found 'substr(secret, 1, 1)'"},
      {"load_extension('/tmp/evil.so') IS NULL",
       "at byte 14, expected the end, found '('"},
      {"length(BlobFromFile('/etc/passwd')) > 0", "at byte 6"},
      {"x = 1; ATTACH DATABASE '/tmp/s.db' AS s", "at byte 5"},
      {"x IN (SELECT id FROM gpkg_contents)", "at byte 13"},
      {"x = 1 -- comment", "at byte 6, expected no comment"},
      {"x = 1 /* comment */", "at byte 6, expected no comment"},
      {"CAST(x AS TEXT) = '1'", "at byte 4"},
      {"x = 'unterminated", "a closing quote (') of the string"},
      {"x NOT 1", "BETWEEN, IN or LIKE after NOT"},
      {"x = 1 ||",
       "at byte 6, expected a field, a literal or an operator, "
       "found '||'"},
      {"", "at byte 0, expected a field, a literal or '('"},
  };
  for (const auto& c : kCases) {
    const Status status = CheckPlainWhereClause(c.where);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.where;
    EXPECT_THAT(status.message(), HasSubstr(c.message)) << c.where;
    EXPECT_THAT(status.message(), HasSubstr("no functions, no sub-selects"));
  }
}

TEST(WhereClauseTest, LengthAndNestingAreBounded) {
  std::string deep(kMaxWhereNesting + 1, '(');
  deep += "x = 1" + std::string(kMaxWhereNesting + 1, ')');
  EXPECT_THAT(CheckPlainWhereClause(deep).message(),
              HasSubstr("at most 32 levels of nesting"));
  std::string negated;
  for (int i = 0; i <= kMaxWhereNesting; ++i) negated += "NOT ";
  EXPECT_FALSE(CheckPlainWhereClause(negated + "x = 1").ok());
  std::string minus(kMaxWhereNesting + 1, '-');
  EXPECT_FALSE(CheckPlainWhereClause("x = " + minus + "1").ok());
  std::string wide = "x IN (1";
  while (wide.size() < kMaxWhereBytes) wide += ",1";
  EXPECT_THAT(CheckPlainWhereClause(wide + ")").message(),
              HasSubstr("at most 4096 are accepted"));
}

}  // namespace
}  // namespace locator::gis
