#include "client/load/svg_writer.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/client/svg_check.h"

namespace locator {
namespace {

using test::CheckSvgText;
using test::SvgSummary;

TEST(XmlEscapeTest, ReplacesTheFiveSpecialCharacters) {
  EXPECT_EQ(XmlEscape(R"(a&b<c>d"e'f)"), "a&amp;b&lt;c&gt;d&quot;e&apos;f");
  EXPECT_EQ(XmlEscape("plain text 1.5 ms"), "plain text 1.5 ms");
  EXPECT_EQ(XmlEscape(""), "");
}

TEST(SvgWriterTest, DocumentIsWellFormedAndKeepsEveryElement) {
  SvgWriter svg(200, 100);
  svg.Rect(0, 0, 200, 100, "fill:white");
  svg.Line({0, 0}, {10, 10}, "stroke:#000;stroke-dasharray:4,2");
  svg.Line({0, 10}, {10, 20}, "stroke:#000");
  const std::vector<SvgPoint> points = {{1, 2}, {3, 4}, {5, 6}};
  svg.Polyline(points, "fill:none;stroke:red");
  svg.Polyline({}, "fill:none;stroke:blue");
  svg.Text({5, 50}, "p99 < 2 ms & \"fast\"", "font:12px sans-serif");
  svg.VerticalText({5, 90}, "latency (ms)", "text-anchor:middle");

  const SvgSummary summary = CheckSvgText(svg.Finish());
  ASSERT_TRUE(summary.well_formed) << summary.error;
  EXPECT_EQ(summary.root, "svg");
  EXPECT_EQ(summary.polyline_points, (std::vector<int>{3, 0}));
  EXPECT_EQ(summary.dashed_lines, 1);
  // The parser gives back the text as written, unescaped.
  EXPECT_EQ(summary.texts, (std::vector<std::string>{"p99 < 2 ms & \"fast\"",
                                                     "latency (ms)"}));
}

TEST(SvgWriterTest, HostileStylesStayInsideTheirAttribute) {
  SvgWriter svg(10, 10);
  svg.Rect(0, 0, 1, 1, "fill:red\"/><script>x</script><rect style=\"");
  const std::string document = svg.Finish();
  EXPECT_EQ(document.find("<script>"), std::string::npos) << document;
  const SvgSummary summary = CheckSvgText(document);
  EXPECT_TRUE(summary.well_formed) << summary.error;
}

TEST(SvgWriterTest, CheckerRejectsABrokenDocument) {
  // The checker must be able to fail, or the tests above prove nothing.
  const SvgSummary summary = CheckSvgText(
      "<svg xmlns=\"http://www.w3.org/2000/svg\"><text>a & b"
      "</text></svg>");
  EXPECT_FALSE(summary.well_formed);
  EXPECT_NE(summary.error.find("not well-formed"), std::string::npos)
      << summary.error;
}

}  // namespace
}  // namespace locator
