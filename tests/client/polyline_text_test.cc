// ParsePolyline: coordinate pairs and WKT LINESTRINGs, and what is wrong
// with a line that does not parse.

#include "client/polyline_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace locator {
namespace {

std::vector<std::pair<double, double>> Pairs(const std::vector<Point2>& line) {
  std::vector<std::pair<double, double>> pairs;
  for (const Point2& p : line) pairs.emplace_back(p.x, p.y);
  return pairs;
}

TEST(PolylineTextTest, CoordinatePairs) {
  std::vector<Point2> line;
  const Status parsed = ParsePolyline(" 0,0\t10.5,-2e1\n-3,4 ", &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(Pairs(line), (std::vector<std::pair<double, double>>{
                             {0, 0}, {10.5, -20}, {-3, 4}}));
}

TEST(PolylineTextTest, WktLineStrings) {
  std::vector<Point2> line;
  Status parsed =
      ParsePolyline("LINESTRING (500000 5500000, 501000.5 5499000)", &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(Pairs(line), (std::vector<std::pair<double, double>>{
                             {500000, 5500000}, {501000.5, 5499000}}));
  parsed = ParsePolyline("linestring(1 2,3 4 , 5 6)", &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(line.size(), 3u);
  // Z is dropped.
  parsed = ParsePolyline("LineString Z (1 2 100, 3 4 200)", &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(Pairs(line),
            (std::vector<std::pair<double, double>>{{1, 2}, {3, 4}}));
}

TEST(PolylineTextTest, NonFiniteValuesAreTheServersToJudge) {
  std::vector<Point2> line;
  ASSERT_TRUE(ParsePolyline("nan,0 1,inf", &line).ok());
  EXPECT_TRUE(std::isnan(line[0].x));
  EXPECT_TRUE(std::isinf(line[1].y));
}

TEST(PolylineTextTest, ProblemsAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "a line needs at least 2 vertices, not 0"},
      {"1,2", "a line needs at least 2 vertices, not 1"},
      {"1,2 3", "'3' is not an x,y pair"},
      {"1,2 3,four", "'four' is not a number"},
      {"1,2 3,4,5", "'4,5' is not a number"},
      {"POINT (1 2)", "WKT: only a LINESTRING is a line, not POINT"},
      {"MULTILINESTRING ((1 2, 3 4))",
       "WKT: only a LINESTRING is a line, not MULTILINESTRING"},
      {"LINESTRING 1 2, 3 4",
       "WKT: expected LINESTRING (x y, ...) with its parentheses"},
      {"LINESTRING (1 2, 3 4",
       "WKT: expected LINESTRING (x y, ...) with its parentheses"},
      {"LINESTRING EMPTY",
       "WKT: expected LINESTRING (x y, ...) with its parentheses"},
      {"LINESTRING (1 2, 3)", "WKT: vertex '3' has 1 coordinates, not 2"},
      {"LINESTRING Z (1 2, 3 4)", "WKT: vertex '1 2' has 2 coordinates, not 3"},
      {"LINESTRING (1 2, 3 y)", "'y' is not a number"},
      {"LINESTRING (1 2)", "a line needs at least 2 vertices, not 1"}};
  for (const auto& [text, problem] : cases) {
    std::vector<Point2> line;
    const Status parsed = ParsePolyline(text, &line);
    EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument) << text;
    EXPECT_EQ(parsed.message(), problem) << text;
  }
}

}  // namespace
}  // namespace locator
