#include "client/load/load_report.h"

#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/json_writer.h"
#include "common/str_cat.h"

namespace locator {
namespace {

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

// The object {count, mean, p50, p90, p99, p99_9, max} in microseconds.
void WriteLatency(const LatencyHistogram& histogram, JsonWriter* json) {
  json->BeginObject();
  json->Key("count").Integer(histogram.count());
  json->Key("mean").Number(histogram.mean());
  for (const NamedPercentile& p : kPercentiles) {
    json->Key(p.name).Integer(histogram.Percentile(p.percent));
  }
  json->Key("max").Integer(histogram.max());
  json->EndObject();
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
  JsonWriter json;
  json.BeginObject();
  json.Key("mode").String(LoadModeName(options.mode));
  json.Key("workload").String(options.workload);
  json.Key("dataset").String(options.scope.dataset);
  json.Key("crs").String(options.scope.crs);
  json.Key("target").String(options.channel.target);
  json.Key("channels").Integer(options.channels);
  json.Key("concurrency").Integer(options.concurrency);
  json.Key("rate").Number(options.rate);
  json.Key("batch_size").Integer(options.points_per_call());
  json.Key("window").Integer(options.window);
  json.Key("measured_seconds").Number(report.measured_seconds);
  json.Key("calls").Integer(totals.calls);
  json.Key("points").Integer(totals.points);
  json.Key("warmup_calls").Integer(totals.warmup_calls);
  json.Key("failed_calls").Integer(report.failed_calls());
  json.Key("calls_per_second").Number(report.calls_per_second());
  json.Key("points_per_second").Number(report.points_per_second());
  json.Key("latency_us");
  WriteLatency(totals.latency, &json);

  json.Key("errors").BeginObject();
  for (const auto& [code, count] : totals.errors) {
    json.Key(code).Integer(count);
  }
  json.EndObject();

  json.Key("cost_window").Integer(totals.cost_window);
  json.Key("cost_window_means").BeginArray();
  for (const double mean : totals.cost_means) json.Number(mean);
  json.EndArray();

  json.Key("phases").BeginArray();
  for (const PhaseTotals& phase : totals.phases) {
    json.BeginObject();
    json.Key("start_seconds").Number(phase.start_seconds);
    json.Key("calls").Integer(phase.latency.count());
    json.Key("failed_calls").Integer(phase.failed_calls);
    json.Key("latency_us");
    WriteLatency(phase.latency, &json);
    json.EndObject();
  }
  json.EndArray();

  json.Key("timeline_seconds").Number(totals.timeline_seconds);
  json.Key("timeline").BeginArray();
  for (const TimelineSlice& slice : totals.timeline) {
    json.BeginObject();
    json.Key("start_seconds").Number(slice.start_seconds);
    json.Key("calls").Integer(slice.calls);
    json.Key("failed_calls").Integer(slice.failed_calls);
    json.Key("p50_us").Integer(slice.p50_us);
    json.Key("p99_us").Integer(slice.p99_us);
    json.Key("queries").Integer(slice.queries);
    json.Key("mean_cost").Number(slice.mean_cost);
    json.EndObject();
  }
  json.EndArray();
  json.EndObject();
  return json.TakeText() + "\n";
}

}  // namespace locator
