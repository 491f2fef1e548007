#include "client/load/load_plot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/client/svg_check.h"

namespace locator {
namespace {

using test::CheckSvgText;
using test::SvgSummary;

// A run of 4 half-second slices, the third without any call, split into
// two phases.
RunTotals FourSliceRun() {
  RunTotals totals;
  totals.timeline_seconds = 0.5;
  for (int i = 0; i < 4; ++i) {
    TimelineSlice slice;
    slice.start_seconds = 0.5 * i;
    if (i != 2) {
      slice.calls = 100;
      slice.p50_us = 400 + 10 * i;
      slice.p99_us = 2500 - 100 * i;
      slice.queries = 100;
      slice.mean_cost = 40.0 / (i + 1);
    }
    totals.timeline.push_back(slice);
  }
  totals.phases.resize(2);
  totals.phases[1].start_seconds = 1.2;
  return totals;
}

bool HasText(const SvgSummary& summary, const std::string& text) {
  return std::find(summary.texts.begin(), summary.texts.end(), text) !=
         summary.texts.end();
}

TEST(LoadPlotTest, DrawsThreeSeriesWithAxesLegendAndPhaseMarks) {
  const SvgSummary summary =
      CheckSvgText(RenderLoadPlot("unary <1-cluster> & co", FourSliceRun()));
  ASSERT_TRUE(summary.well_formed) << summary.error;
  // p50, p99 and cost, each with a point per slice that has data.
  EXPECT_EQ(summary.polyline_points, (std::vector<int>{3, 3, 3}));
  // One phase began after the first.
  EXPECT_EQ(summary.dashed_lines, 1);
  EXPECT_TRUE(HasText(summary, "phase 2"));
  EXPECT_TRUE(HasText(summary, "unary <1-cluster> & co"));
  EXPECT_TRUE(HasText(summary, "latency (ms)"));
  EXPECT_TRUE(HasText(summary, "server cost per query"));
  for (const char* legend : {"p50", "p99", "mean cost"}) {
    EXPECT_TRUE(HasText(summary, legend)) << legend;
  }
  // Tick labels: the largest p99 is 2.5 ms, the largest cost 40.
  EXPECT_TRUE(HasText(summary, "2.5"));
  EXPECT_TRUE(HasText(summary, "40"));
}

TEST(LoadPlotTest, AnEmptyRunStillMakesAValidChart) {
  const std::string svg = RenderLoadPlot("empty", RunTotals());
  // Well-formed is not enough: no coordinate may be computed from a 0/0.
  EXPECT_EQ(svg.find("nan"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("inf"), std::string::npos) << svg;
  const SvgSummary summary = CheckSvgText(svg);
  ASSERT_TRUE(summary.well_formed) << summary.error;
  EXPECT_EQ(summary.polyline_points, (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(summary.dashed_lines, 0);
}

}  // namespace
}  // namespace locator
