// End to end: a short `locator-load` run against a real locatord. The JSON
// summary must show throughput, no failed call, cost windows and a
// timeline; --plot must write a well-formed chart of it.

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/client/svg_check.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/server_process.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::RunBinary;
using test::ServerProcess;
using test::SvgSummary;

double Number(const google::protobuf::Struct& object, const std::string& key) {
  const auto found = object.fields().find(key);
  EXPECT_NE(found, object.fields().end()) << key;
  return found == object.fields().end() ? 0 : found->second.number_value();
}

// Runs locator-load for 2 s, with `args` added, against a fresh locatord
// on 5000 uniform points; it must succeed. Its JSON report goes to
// `summary`.
void RunShortLoad(const std::vector<std::string>& args,
                  google::protobuf::Struct* summary) {
  std::unique_ptr<ServerProcess> server;
  const Status started = ServerProcess::Start(
      LOCATORD_PATH, {"--dataset", "uniform:5000:1", "--listen", "127.0.0.1:0"},
      &server);
  ASSERT_TRUE(started.ok()) << started.ToString();

  std::vector<std::string> all = {"--target", server->target(), "--duration",
                                  "2",        "--format",       "json"};
  all.insert(all.end(), args.begin(), args.end());
  const BinaryResult result = RunBinary(LOCATOR_LOAD_PATH, all);
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, summary).ok())
      << result.out;
}

TEST(LocatorLoadTest, ShortRunReportsThroughputAndNoErrors) {
  google::protobuf::Struct summary;
  ASSERT_NO_FATAL_FAILURE(RunShortLoad(
      {"--warmup", "0.5", "--concurrency", "8", "--cost-window", "100"},
      &summary));
  EXPECT_GT(Number(summary, "calls_per_second"), 0);
  EXPECT_GT(Number(summary, "points_per_second"), 0);
  EXPECT_GT(Number(summary, "warmup_calls"), 0);
  EXPECT_EQ(Number(summary, "failed_calls"), 0);
  EXPECT_TRUE(summary.fields().at("errors").struct_value().fields().empty());
  const google::protobuf::Struct& latency =
      summary.fields().at("latency_us").struct_value();
  EXPECT_GT(Number(latency, "count"), 0);
  EXPECT_LE(Number(latency, "p50"), Number(latency, "p99"));
  EXPECT_LE(Number(latency, "p99"), Number(latency, "max"));
  EXPECT_GT(summary.fields().at("cost_window_means").list_value().values_size(),
            0);
}

TEST(LocatorLoadTest, PlotsLatencyAndCostOverTime) {
  const std::string plot = ::testing::TempDir() + "locator_load_plot.svg";
  unlink(plot.c_str());
  google::protobuf::Struct summary;
  ASSERT_NO_FATAL_FAILURE(
      RunShortLoad({"--concurrency", "4", "--workload", "1-cluster",
                    "--timeline-s", "0.5", "--plot", plot},
                   &summary));

  EXPECT_EQ(Number(summary, "timeline_seconds"), 0.5);
  const auto& timeline = summary.fields().at("timeline").list_value();
  // 2 s in half-second slices (the last call may end in a fifth).
  EXPECT_GE(timeline.values_size(), 4);
  EXPECT_GT(Number(timeline.values(0).struct_value(), "calls"), 0);
  EXPECT_EQ(summary.fields().at("phases").list_value().values_size(), 1);

  const SvgSummary chart = test::CheckSvgFile(plot);
  ASSERT_TRUE(chart.well_formed) << chart.error;
  ASSERT_EQ(chart.polyline_points.size(), 3u);
  for (int points : chart.polyline_points) {
    EXPECT_GE(points, 4);
  }
  unlink(plot.c_str());
}

TEST(LocatorLoadTest, UnwritablePlotIsAUsageError) {
  const BinaryResult result = RunBinary(
      LOCATOR_LOAD_PATH,
      {"--plot", "/nonexistent-dir/plot.svg", "--target", "127.0.0.1:1"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--plot"), std::string::npos) << result.err;
}

TEST(LocatorLoadTest, BadFlagIsAUsageError) {
  const BinaryResult result =
      RunBinary(LOCATOR_LOAD_PATH, {"--concurrency", "0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--concurrency"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace locator
