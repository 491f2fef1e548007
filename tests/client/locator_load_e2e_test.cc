// End to end: a short `locator-load` run against a real locatord. The JSON
// summary must show throughput, no failed call, and cost windows.

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "tests/testing/run_binary.h"
#include "tests/testing/server_process.h"

namespace locator {
namespace {

using testing::BinaryResult;
using testing::RunBinary;
using testing::ServerProcess;

double Number(const google::protobuf::Struct& object, const std::string& key) {
  const auto found = object.fields().find(key);
  EXPECT_NE(found, object.fields().end()) << key;
  return found == object.fields().end() ? 0 : found->second.number_value();
}

TEST(LocatorLoadTest, ShortRunReportsThroughputAndNoErrors) {
  std::unique_ptr<ServerProcess> server;
  const Status started = ServerProcess::Start(
      LOCATORD_PATH, {"--dataset", "uniform:5000:1", "--listen", "127.0.0.1:0"},
      &server);
  ASSERT_TRUE(started.ok()) << started.ToString();

  const BinaryResult result = RunBinary(
      LOCATOR_LOAD_PATH,
      {"--target", server->target(), "--duration", "2", "--warmup", "0.5",
       "--concurrency", "8", "--cost-window", "100", "--format", "json"});
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out;

  google::protobuf::Struct summary;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, &summary).ok())
      << result.out;
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

TEST(LocatorLoadTest, BadFlagIsAUsageError) {
  const BinaryResult result =
      RunBinary(LOCATOR_LOAD_PATH, {"--concurrency", "0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--concurrency"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace locator
