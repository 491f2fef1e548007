#include "server/serving/stats_redaction.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace locator {
namespace {

TEST(RedactPathsTest, AnAliasReplacesItsPathKeepingLineAndReason) {
  const std::vector<PathAlias> aliases = {
      {.path = "/srv/reload/bad.csv", .shown = "bad.csv"}};
  EXPECT_EQ(
      RedactPaths("/srv/reload/bad.csv:3: 'oops' is not a number", aliases),
      "bad.csv:3: 'oops' is not a number");
  EXPECT_EQ(RedactPaths("cannot read '/srv/reload/bad.csv': denied", aliases),
            "cannot read 'bad.csv': denied");
}

TEST(RedactPathsTest, TheLongestAliasWinsAndOnlyWhole) {
  const std::vector<PathAlias> aliases = {
      {.path = "/srv/t.gpkg", .shown = "t.gpkg"},
      {.path = "/srv/t.gpkg?layer=pts", .shown = "t.gpkg?layer=pts"},
      {.path = "t.csv", .shown = "dataset 'default'"}};
  EXPECT_EQ(RedactPaths("/srv/t.gpkg?layer=pts: no points", aliases),
            "t.gpkg?layer=pts: no points");
  EXPECT_EQ(RedactPaths("/srv/t.gpkg: no layer 'pts'", aliases),
            "t.gpkg: no layer 'pts'");
  // Not inside a longer word.
  EXPECT_EQ(RedactPaths("t.csv:3: not t.csvx nor at.csv", aliases),
            "dataset 'default':3: not t.csvx nor at.csv");
}

TEST(RedactPathsTest, OtherAbsolutePathsAreCutToTheirLastComponent) {
  EXPECT_EQ(RedactPaths("/srv/data/mesh.node:5: bad index", {}),
            "mesh.node:5: bad index");
  EXPECT_EQ(
      RedactPaths("cannot make the state dir /var/state/terrain: denied", {}),
      "cannot make the state dir terrain: denied");
  EXPECT_EQ(RedactPaths("spec '/srv/p.csv+/srv/c.wkt' (see /srv/dir/)", {}),
            "spec 'p.csv+c.wkt' (see dir)");
  EXPECT_EQ(RedactPaths("x=/a/b, y=/c", {}), "x=b, y=c");
}

TEST(RedactPathsTest, TextWithoutPathsIsUnchanged) {
  for (const std::string_view text :
       {"", "1/2 of the points", "bad dataset spec 'uniform:0': n >= 3",
        "a / b", "/"}) {
    EXPECT_EQ(RedactPaths(text, {}), text);
  }
}

}  // namespace
}  // namespace locator
