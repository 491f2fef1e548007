#include "client/load/load_options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace locator {
namespace {

// The error message of parsing `args`, which must fail.
std::string ErrorOf(const std::vector<std::string>& args) {
  LoadOptions options;
  const Status status = ParseLoadOptions(args, &options);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  return status.message();
}

TEST(LoadOptionsTest, Defaults) {
  LoadOptions options;
  ASSERT_TRUE(ParseLoadOptions({}, &options).ok());
  EXPECT_EQ(options.channel.target, "127.0.0.1:50051");
  EXPECT_EQ(options.mode, LoadMode::kUnary);
  EXPECT_EQ(options.workload, "uniform");
  EXPECT_EQ(options.concurrency, 64u);
  EXPECT_EQ(options.channels, 2u);
  EXPECT_EQ(options.rate, 0);
  EXPECT_EQ(options.length.measured_seconds, 10);
  EXPECT_FALSE(options.length.by_count());
  EXPECT_EQ(options.deadline_ms, 5000);
  EXPECT_EQ(options.cost_window, 500u);
  EXPECT_EQ(options.format, ReportFormat::kText);
  EXPECT_EQ(options.timeline_seconds, 1);
  EXPECT_TRUE(options.plot_path.empty());
  EXPECT_FALSE(options.phase_signal);
  EXPECT_EQ(options.points_per_call(), 1u);
  EXPECT_FALSE(options.help);
}

TEST(LoadOptionsTest, ParsesEveryFlag) {
  LoadOptions options;
  const Status status = ParseLoadOptions({"--target",
                                          "127.0.0.1:9",
                                          "--mode",
                                          "batch",
                                          "--workload",
                                          "1-cluster",
                                          "--seed",
                                          "7",
                                          "--concurrency",
                                          "8",
                                          "--batch-size",
                                          "500",
                                          "--all-columns",
                                          "--channels",
                                          "3",
                                          "--queries",
                                          "1000",
                                          "--warmup",
                                          "200",
                                          "--time-limit",
                                          "30",
                                          "--deadline-ms",
                                          "250",
                                          "--retry",
                                          "--cost-window",
                                          "100",
                                          "--format",
                                          "json",
                                          "--rate",
                                          "50",
                                          "--timeline-s",
                                          "0.25",
                                          "--plot",
                                          "run.svg",
                                          "--phase-signal"},
                                         &options);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(options.channel.target, "127.0.0.1:9");
  EXPECT_TRUE(options.channel.retry_unavailable);
  EXPECT_EQ(options.mode, LoadMode::kBatch);
  EXPECT_EQ(options.workload, "1-cluster");
  EXPECT_EQ(options.seed, 7u);
  EXPECT_EQ(options.concurrency, 8u);
  EXPECT_EQ(options.points_per_call(), 500u);
  EXPECT_TRUE(options.all_columns);
  EXPECT_EQ(options.channels, 3u);
  EXPECT_TRUE(options.length.by_count());
  EXPECT_EQ(options.length.measured_queries, 1000u);
  EXPECT_EQ(options.length.warmup_queries, 200u);
  EXPECT_EQ(options.length.time_limit_seconds, 30);
  EXPECT_EQ(options.deadline_ms, 250);
  EXPECT_EQ(options.cost_window, 100u);
  EXPECT_EQ(options.format, ReportFormat::kJson);
  EXPECT_EQ(options.rate, 50);
  EXPECT_EQ(options.timeline_seconds, 0.25);
  EXPECT_EQ(options.plot_path, "run.svg");
  EXPECT_TRUE(options.phase_signal);
}

TEST(LoadOptionsTest, WarmupIsInSecondsForTimedRuns) {
  LoadOptions options;
  ASSERT_TRUE(
      ParseLoadOptions({"--duration", "3", "--warmup", "1.5"}, &options).ok());
  EXPECT_EQ(options.length.measured_seconds, 3);
  EXPECT_EQ(options.length.warmup_seconds, 1.5);
}

TEST(LoadOptionsTest, StreamModeAndReplayWorkload) {
  LoadOptions options;
  ASSERT_TRUE(ParseLoadOptions({"--mode", "stream", "--window", "4",
                                "--workload", "file:/tmp/queries.csv"},
                               &options)
                  .ok());
  EXPECT_EQ(options.mode, LoadMode::kStream);
  EXPECT_EQ(options.window, 4u);
  EXPECT_EQ(options.workload, "file:/tmp/queries.csv");
}

TEST(LoadOptionsTest, DatasetAndCrsMakeTheScope) {
  LoadOptions options;
  ASSERT_TRUE(ParseLoadOptions({"--dataset", "terrain"}, &options).ok());
  EXPECT_EQ(options.scope.dataset, "terrain");
  EXPECT_EQ(options.scope.crs, "");
  ASSERT_TRUE(ParseLoadOptions({"--crs", "EPSG:4326", "--workload",
                                "file:/tmp/lonlat.csv", "--mode", "batch"},
                               &options)
                  .ok());
  EXPECT_EQ(options.scope.dataset, "");
  EXPECT_EQ(options.scope.crs, "EPSG:4326");
  EXPECT_EQ(options.scope.interpolation, v1::INTERPOLATION_UNSPECIFIED);
}

TEST(LoadOptionsTest, HelpIsNotAnError) {
  LoadOptions options;
  ASSERT_TRUE(ParseLoadOptions({"--help"}, &options).ok());
  EXPECT_TRUE(options.help);
  EXPECT_NE(LoadUsage().find("--concurrency"), std::string::npos);
}

TEST(LoadOptionsTest, RejectsBadValues) {
  EXPECT_NE(ErrorOf({"--concurrency", "0"}).find("--concurrency"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--concurrency", "-3"}).find("--concurrency"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--channels", "0"}).find("--channels"), std::string::npos);
  EXPECT_NE(ErrorOf({"--batch-size", "abc"}).find("batch-size"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--deadline-ms", "0"}).find("--deadline-ms"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--cost-window", "0"}).find("--cost-window"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--mode", "bogus"}).find("--mode"), std::string::npos);
  EXPECT_NE(ErrorOf({"--workload", "bogus"}).find("bogus"), std::string::npos);
  EXPECT_NE(ErrorOf({"--workload", "file:"}).find("path"), std::string::npos);
  EXPECT_NE(ErrorOf({"--rate", "-1"}).find("--rate"), std::string::npos);
  EXPECT_NE(ErrorOf({"--format", "xml"}).find("--format"), std::string::npos);
  EXPECT_NE(ErrorOf({"--duration", "0"}).find("--duration"), std::string::npos);
  EXPECT_NE(ErrorOf({"--queries", "0"}).find("--queries"), std::string::npos);
  EXPECT_NE(ErrorOf({"--time-limit", "0"}).find("--time-limit"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--warmup", "-1"}).find("--warmup"), std::string::npos);
  EXPECT_NE(ErrorOf({"--timeline-s", "0.01"}).find("--timeline-s"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--timeline-s", "nan"}).find("--timeline-s"),
            std::string::npos);
}

TEST(LoadOptionsTest, RejectsConflictingFlags) {
  EXPECT_NE(ErrorOf({"--duration", "1", "--queries", "10"}).find("not both"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf({"--queries", "10", "--warmup", "1.5"}).find("whole number"),
      std::string::npos);
  EXPECT_NE(ErrorOf({"--mode", "stream", "--rate", "100"}).find("--rate"),
            std::string::npos);
  EXPECT_EQ(ErrorOf({"--crs", "EPSG:4326", "--workload", "1-cluster"}),
            "--crs needs a --workload file:PATH: generated workloads lie in "
            "the dataset's bounding box, in its own coordinates");
  EXPECT_EQ(ErrorOf({"--mode", "nested-batch", "--dataset", "terrain"}),
            "--dataset and --crs are for the Locator service; nested-batch "
            "calls the bench service, which has neither");
}

TEST(LoadOptionsTest, ErrorsNameTheFlagAndTheForm) {
  EXPECT_EQ(ErrorOf({"--concurrency", "0"}),
            "--concurrency '0': must be a whole number >= 1");
  EXPECT_EQ(ErrorOf({"--mode=bogus"}),
            "--mode 'bogus': must be unary, batch, stream or nested-batch");
  EXPECT_EQ(ErrorOf({"--timeline-s", "0.01"}),
            "--timeline-s '0.01': must be a number of seconds >= 0.1");
  EXPECT_EQ(ErrorOf({"--concurrency", "2", "--concurrency", "3"}),
            "--concurrency is given twice");
  LoadOptions options;
  ASSERT_TRUE(ParseLoadOptions(
                  {"--mode=stream", "--window=4", "--duration=2.5"}, &options)
                  .ok());
  EXPECT_EQ(options.mode, LoadMode::kStream);
  EXPECT_EQ(options.window, 4u);
  EXPECT_EQ(options.length.measured_seconds, 2.5);
}

TEST(LoadOptionsTest, RejectsUnknownFlagsAndPositionals) {
  EXPECT_FALSE(ErrorOf({"--bogus"}).empty());
  EXPECT_FALSE(ErrorOf({"--conc", "4"}).empty());  // no prefix guessing
  EXPECT_FALSE(ErrorOf({"stray"}).empty());
}

}  // namespace
}  // namespace locator
