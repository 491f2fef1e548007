#include "client/load/load_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "client/load/svg_writer.h"
#include "common/str_cat.h"

namespace locator {
namespace {

constexpr double kWidth = 900;
constexpr double kHeight = 600;
constexpr double kLeft = 80;    // room for y tick labels and the axis title
constexpr double kRight = 870;  // the plot area's right edge
constexpr int kTicks = 5;       // about this many ticks per axis

constexpr char kFrameStyle[] = "fill:none;stroke:#333;stroke-width:1";
constexpr char kGridStyle[] = "stroke:#ddd;stroke-width:1";
constexpr char kLabelStyle[] = "font:12px sans-serif;fill:#333";
constexpr char kTitleStyle[] = "font:bold 15px sans-serif;fill:#111";
constexpr char kMarkStyle[] = "stroke:#888;stroke-width:1;stroke-dasharray:6,4";

// One plotted series: a colour and how to read a slice's value (false when
// the slice has none).
struct Series {
  std::string_view name;
  std::string_view colour;
  std::function<bool(const TimelineSlice&, double*)> value;
};

// A panel: the vertical extent of its plot area and its y axis title.
struct Panel {
  double top = 0;
  double bottom = 0;
  std::string_view y_title;
};

std::string TickLabel(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

// A 1, 2 or 5 times a power of ten, so that about kTicks ticks span
// [0, max].
double TickStep(double max) {
  const double raw = max / kTicks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalized = raw / magnitude;
  const double nice = normalized <= 1   ? 1
                      : normalized <= 2 ? 2
                      : normalized <= 5 ? 5
                                        : 10;
  return nice * magnitude;
}

class Chart {
 public:
  explicit Chart(const RunTotals& totals)
      : totals_(totals),
        // At least a second, so that an empty run still has an axis.
        x_max_(std::max(1.0, static_cast<double>(totals.timeline.size()) *
                                 totals.timeline_seconds)),
        x_step_(TickStep(x_max_)) {}

  double X(double seconds) const {
    return kLeft + (kRight - kLeft) * seconds / x_max_;
  }

  // The panel's frame, grid, y ticks and title, with its series and legend.
  void DrawPanel(const Panel& panel, std::span<const Series> series) {
    double max = 0;
    for (const Series& s : series) {
      for (const TimelineSlice& slice : totals_.timeline) {
        double value = 0;
        if (s.value(slice, &value)) max = std::max(max, value);
      }
    }
    if (max <= 0) max = 1;
    const double y_step = TickStep(max);
    // The axis runs from 0 to the first tick at or above the largest value.
    const double y_max = std::ceil(max / y_step) * y_step;
    const auto y = [&](double value) {
      return panel.bottom - (panel.bottom - panel.top) * value / y_max;
    };
    for (double tick = 0; tick <= y_max + y_step / 2; tick += y_step) {
      svg_.Line({kLeft, y(tick)}, {kRight, y(tick)}, kGridStyle);
      svg_.Text({kLeft - 6, y(tick) + 4}, TickLabel(tick),
                StrCat({kLabelStyle, ";text-anchor:end"}));
    }
    for (double tick = 0; tick <= x_max_ + x_step_ / 2; tick += x_step_) {
      svg_.Line({X(tick), panel.bottom}, {X(tick), panel.bottom + 4},
                kFrameStyle);
      svg_.Text({X(tick), panel.bottom + 17}, TickLabel(tick),
                StrCat({kLabelStyle, ";text-anchor:middle"}));
    }
    svg_.Rect(kLeft, panel.top, kRight - kLeft, panel.bottom - panel.top,
              kFrameStyle);
    svg_.VerticalText({24, (panel.top + panel.bottom) / 2}, panel.y_title,
                      StrCat({kLabelStyle, ";text-anchor:middle"}));
    double legend_y = panel.top + 16;
    for (const Series& s : series) {
      std::vector<SvgPoint> points;
      for (const TimelineSlice& slice : totals_.timeline) {
        double value = 0;
        if (!s.value(slice, &value)) continue;
        points.push_back(
            {X(slice.start_seconds + totals_.timeline_seconds / 2), y(value)});
      }
      const std::string style =
          StrCat({"fill:none;stroke-width:2;stroke:", s.colour});
      svg_.Polyline(points, style);
      svg_.Line({kRight - 110, legend_y - 4}, {kRight - 86, legend_y - 4},
                style);
      svg_.Text({kRight - 80, legend_y}, s.name, kLabelStyle);
      legend_y += 18;
    }
  }

  // A dashed line across both panels where each phase after the first
  // began.
  void DrawPhaseMarks(double top, double bottom) {
    for (size_t i = 1; i < totals_.phases.size(); ++i) {
      const double x = X(totals_.phases[i].start_seconds);
      svg_.Line({x, top}, {x, bottom}, kMarkStyle);
      svg_.Text({x + 4, top + 12}, StrCat({"phase ", std::to_string(i + 1)}),
                kLabelStyle);
    }
  }

  SvgWriter& svg() { return svg_; }

 private:
  const RunTotals& totals_;
  const double x_max_;
  const double x_step_;
  SvgWriter svg_{kWidth, kHeight};
};

}  // namespace

std::string RenderLoadPlot(std::string_view title, const RunTotals& totals) {
  Chart chart(totals);
  SvgWriter& svg = chart.svg();
  svg.Rect(0, 0, kWidth, kHeight, "fill:white;stroke:none");
  svg.Text({kLeft, 26}, title, kTitleStyle);

  const auto latency_ms = [](uint64_t TimelineSlice::*field) {
    return [field](const TimelineSlice& slice, double* value) {
      *value = static_cast<double>(slice.*field) / 1000.0;
      return slice.calls > 0;
    };
  };
  const Series latency[] = {
      {"p50", "#1f77b4", latency_ms(&TimelineSlice::p50_us)},
      {"p99", "#d62728", latency_ms(&TimelineSlice::p99_us)}};
  chart.DrawPanel({50, 300, "latency (ms)"}, latency);

  const Series cost[] = {
      {"mean cost", "#2ca02c", [](const TimelineSlice& slice, double* value) {
         *value = slice.mean_cost;
         return slice.queries > 0;
       }}};
  chart.DrawPanel({350, 540, "server cost per query"}, cost);
  chart.DrawPhaseMarks(50, 540);

  svg.Text({(kLeft + kRight) / 2, 585},
           StrCat({"seconds since the start of the run (slices of ",
                   TickLabel(totals.timeline_seconds), " s)"}),
           StrCat({kLabelStyle, ";text-anchor:middle"}));
  return svg.Finish();
}

}  // namespace locator
