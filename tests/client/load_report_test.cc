// locator-load's JSON report: one JSON object that scripts read back, with
// every documented field (load_report.h) holding what the run measured.

#include "client/load/load_report.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <string>

namespace locator {
namespace {

using google::protobuf::Struct;
using google::protobuf::Value;

const Value& Field(const Struct& object, const std::string& key) {
  static const Value* missing = new Value();
  const auto it = object.fields().find(key);
  EXPECT_NE(it, object.fields().end()) << key;
  return it == object.fields().end() ? *missing : it->second;
}

LoadReport SampleReport() {
  LoadReport report;
  report.measured_seconds = 2;
  RunTotals& totals = report.totals;
  for (const uint64_t micros : {100, 200, 300, 4000}) {
    totals.latency.Record(micros);
  }
  totals.calls = 4;
  totals.points = 40;
  totals.warmup_calls = 1;
  totals.errors = {{"UNAVAILABLE", 2}, {"DEADLINE_EXCEEDED", 1}};
  totals.cost_window = 10;
  totals.cost_means = {3.5, 2.25};
  PhaseTotals phase;
  phase.start_seconds = 0.5;
  phase.latency = totals.latency;
  phase.failed_calls = 3;
  totals.phases = {phase};
  totals.timeline_seconds = 1;
  TimelineSlice slice;
  slice.calls = 4;
  slice.p99_us = 4000;
  slice.mean_cost = 2.75;
  totals.timeline = {slice};
  return report;
}

TEST(LoadReportJsonTest, IsOneObjectWithTheMeasuredFields) {
  LoadOptions options;
  options.workload = "uniform \"quoted\"";
  const std::string text = FormatReportJson(options, SampleReport());
  ASSERT_EQ(text.back(), '\n');
  Struct report;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(text, &report).ok())
      << text;
  EXPECT_EQ(Field(report, "workload").string_value(), "uniform \"quoted\"");
  EXPECT_EQ(Field(report, "mode").string_value(), "unary");
  EXPECT_EQ(Field(report, "calls").number_value(), 4);
  EXPECT_EQ(Field(report, "points").number_value(), 40);
  EXPECT_EQ(Field(report, "failed_calls").number_value(), 3);
  EXPECT_EQ(Field(report, "calls_per_second").number_value(), 2);
  EXPECT_EQ(Field(report, "points_per_second").number_value(), 20);
  const Struct& latency = Field(report, "latency_us").struct_value();
  EXPECT_EQ(Field(latency, "count").number_value(), 4);
  EXPECT_EQ(Field(latency, "mean").number_value(), 1150);
  EXPECT_EQ(Field(latency, "max").number_value(), 4000);
  EXPECT_LE(Field(latency, "p50").number_value(),
            Field(latency, "p99_9").number_value());
  const Struct& errors = Field(report, "errors").struct_value();
  EXPECT_EQ(Field(errors, "UNAVAILABLE").number_value(), 2);
  EXPECT_EQ(Field(errors, "DEADLINE_EXCEEDED").number_value(), 1);
  const auto& means = Field(report, "cost_window_means").list_value();
  ASSERT_EQ(means.values_size(), 2);
  EXPECT_EQ(means.values(1).number_value(), 2.25);
  const auto& phases = Field(report, "phases").list_value();
  ASSERT_EQ(phases.values_size(), 1);
  EXPECT_EQ(
      Field(phases.values(0).struct_value(), "failed_calls").number_value(), 3);
  const auto& timeline = Field(report, "timeline").list_value();
  ASSERT_EQ(timeline.values_size(), 1);
  EXPECT_EQ(
      Field(timeline.values(0).struct_value(), "mean_cost").number_value(),
      2.75);
}

}  // namespace
}  // namespace locator
