#include "client/load/load_report.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/str_cat.h"

namespace locator {
namespace {

using google::protobuf::Struct;

struct NamedPercentile {
  std::string_view name;
  double percent;
};
constexpr NamedPercentile kPercentiles[] = {
    {"p50", 50}, {"p90", 90}, {"p99", 99}, {"p99_9", 99.9}};

// Text shows this many cost windows; JSON has them all.
constexpr size_t kCostWindowsShown = 12;

std::string Fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string RunShape(const LoadOptions& options) {
  std::string shape(LoadModeName(options.mode));
  if (options.points_per_call() > 1) {
    shape.append(
        StrCat({" of ", std::to_string(options.points_per_call()), " points"}));
  }
  if (options.rate > 0) {
    return StrCat(
        {shape, ", open loop at ", Fixed(options.rate, 1), " calls/s"});
  }
  shape.append(
      StrCat({", closed loop, ", std::to_string(options.concurrency)}));
  if (options.mode == LoadMode::kStream) {
    shape.append(StrCat({" streams x ", std::to_string(options.window)}));
  }
  return StrCat({shape, " in flight"});
}

void Set(Struct& object, std::string_view key, double number) {
  (*object.mutable_fields())[std::string(key)].set_number_value(number);
}

void Set(Struct& object, std::string_view key, std::string text) {
  (*object.mutable_fields())[std::string(key)].set_string_value(
      std::move(text));
}

Struct& SetObject(Struct& object, std::string_view key) {
  return *(*object.mutable_fields())[std::string(key)].mutable_struct_value();
}

google::protobuf::ListValue& SetList(Struct& object, std::string_view key) {
  return *(*object.mutable_fields())[std::string(key)].mutable_list_value();
}

// {count, mean, p50, p90, p99, p99_9, max} in microseconds.
void SetLatency(Struct& latency, const LatencyHistogram& histogram) {
  Set(latency, "count", histogram.count());
  Set(latency, "mean", histogram.mean());
  for (const NamedPercentile& p : kPercentiles) {
    Set(latency, p.name, histogram.Percentile(p.percent));
  }
  Set(latency, "max", histogram.max());
}

// One line per phase, when the run was split into phases.
std::string PhaseLines(const std::vector<PhaseTotals>& phases) {
  if (phases.size() < 2) return "";
  std::string text;
  for (size_t i = 0; i < phases.size(); ++i) {
    const PhaseTotals& phase = phases[i];
    text.append(StrCat({"phase ", std::to_string(i + 1), "     from ",
                        Fixed(phase.start_seconds, 2), " s: ",
                        std::to_string(phase.latency.count()), " calls, ",
                        std::to_string(phase.failed_calls), " failed, p50 ",
                        FormatMicros(phase.latency.Percentile(50)), ", p99 ",
                        FormatMicros(phase.latency.Percentile(99)), "\n"}));
  }
  return text;
}

}  // namespace

uint64_t LoadReport::failed_calls() const {
  uint64_t failed = 0;
  for (const auto& [code, count] : totals.errors) failed += count;
  return failed;
}

double LoadReport::calls_per_second() const {
  return measured_seconds > 0 ? totals.calls / measured_seconds : 0;
}

double LoadReport::points_per_second() const {
  return measured_seconds > 0 ? totals.points / measured_seconds : 0;
}

std::string FormatMicros(uint64_t micros) {
  if (micros < 1000) return StrCat({std::to_string(micros), " us"});
  if (micros < 1'000'000) return StrCat({Fixed(micros / 1e3, 2), " ms"});
  return StrCat({Fixed(micros / 1e6, 2), " s"});
}

std::string DescribeRun(const LoadOptions& options) {
  std::string run =
      StrCat({RunShape(options), "; workload ", options.workload});
  if (!options.scope.crs.empty()) {
    run += StrCat({" in ", options.scope.crs});
  }
  if (!options.scope.dataset.empty()) {
    run += StrCat({"; dataset ", options.scope.dataset});
  }
  return StrCat({run, "; ", std::to_string(options.channels), " channels to ",
                 options.channel.target});
}

std::string FormatReportText(const LoadOptions& options,
                             const LoadReport& report) {
  const RunTotals& totals = report.totals;
  std::string text = StrCat({"run         ", DescribeRun(options), "\n"});
  text.append(
      StrCat({"measured    ", Fixed(report.measured_seconds, 2),
              " s: ", std::to_string(totals.calls), " calls, ",
              std::to_string(totals.points), " points (after ",
              std::to_string(totals.warmup_calls), " warm-up calls)\n"}));
  text.append(
      StrCat({"throughput  ", Fixed(report.calls_per_second(), 1), " calls/s, ",
              Fixed(report.points_per_second(), 1), " points/s\n"}));
  text.append("latency    ");
  for (const NamedPercentile& p : kPercentiles) {
    text.append(
        StrCat({" ", p.name, " ",
                FormatMicros(totals.latency.Percentile(p.percent)), ","}));
  }
  text.append(StrCat(
      {" max ", FormatMicros(totals.latency.max()), " (mean ",
       FormatMicros(static_cast<uint64_t>(totals.latency.mean())), ")\n"}));
  text.append("errors     ");
  if (totals.errors.empty()) text.append(" none");
  for (const auto& [code, count] : totals.errors) {
    text.append(StrCat({" ", code, " ", std::to_string(count)}));
  }
  text.append(
      StrCat({"\ncost        mean per ", std::to_string(totals.cost_window),
              " queries, in arrival order:"}));
  const std::vector<double>& means = totals.cost_means;
  for (size_t i = 0; i < means.size() && i < kCostWindowsShown; ++i) {
    text.append(StrCat({" ", Fixed(means[i], 1)}));
  }
  if (means.size() > kCostWindowsShown) {
    text.append(StrCat({" ... ", Fixed(means.back(), 1), " (",
                        std::to_string(means.size()),
                        " windows; all with --format json)"}));
  }
  text.push_back('\n');
  text.append(PhaseLines(totals.phases));
  return text;
}

std::string FormatReportJson(const LoadOptions& options,
                             const LoadReport& report) {
  const RunTotals& totals = report.totals;
  Struct summary;
  Set(summary, "mode", std::string(LoadModeName(options.mode)));
  Set(summary, "workload", options.workload);
  Set(summary, "dataset", options.scope.dataset);
  Set(summary, "crs", options.scope.crs);
  Set(summary, "target", options.channel.target);
  Set(summary, "channels", options.channels);
  Set(summary, "concurrency", options.concurrency);
  Set(summary, "rate", options.rate);
  Set(summary, "batch_size", options.points_per_call());
  Set(summary, "window", options.window);
  Set(summary, "measured_seconds", report.measured_seconds);
  Set(summary, "calls", totals.calls);
  Set(summary, "points", totals.points);
  Set(summary, "warmup_calls", totals.warmup_calls);
  Set(summary, "failed_calls", report.failed_calls());
  Set(summary, "calls_per_second", report.calls_per_second());
  Set(summary, "points_per_second", report.points_per_second());

  SetLatency(SetObject(summary, "latency_us"), totals.latency);

  Struct& errors = SetObject(summary, "errors");
  for (const auto& [code, count] : totals.errors) Set(errors, code, count);

  Set(summary, "cost_window", totals.cost_window);
  google::protobuf::ListValue& means = SetList(summary, "cost_window_means");
  for (double mean : totals.cost_means) {
    means.add_values()->set_number_value(mean);
  }

  google::protobuf::ListValue& phases = SetList(summary, "phases");
  for (const PhaseTotals& phase : totals.phases) {
    Struct& entry = *phases.add_values()->mutable_struct_value();
    Set(entry, "start_seconds", phase.start_seconds);
    Set(entry, "calls", phase.latency.count());
    Set(entry, "failed_calls", phase.failed_calls);
    SetLatency(SetObject(entry, "latency_us"), phase.latency);
  }

  Set(summary, "timeline_seconds", totals.timeline_seconds);
  google::protobuf::ListValue& timeline = SetList(summary, "timeline");
  for (const TimelineSlice& slice : totals.timeline) {
    Struct& entry = *timeline.add_values()->mutable_struct_value();
    Set(entry, "start_seconds", slice.start_seconds);
    Set(entry, "calls", slice.calls);
    Set(entry, "failed_calls", slice.failed_calls);
    Set(entry, "p50_us", slice.p50_us);
    Set(entry, "p99_us", slice.p99_us);
    Set(entry, "queries", slice.queries);
    Set(entry, "mean_cost", slice.mean_cost);
  }

  std::string json;
  // Printing a Struct of numbers and strings cannot fail.
  (void)google::protobuf::util::MessageToJsonString(summary, &json);
  return json + "\n";
}

}  // namespace locator
