// End to end: the requests the real `locator` and `locator-load` binaries
// send for --dataset, --crs and --interpolation, seen by the fake server of
// this process (fake_locator_server.h), and `locator datasets`.

#include <gmock/gmock.h>
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "tests/client/fake_locator_server.h"
#include "tests/core/scratch_dir.h"
#include "tests/testing/run_binary.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::FakeLocatorServer;
using test::RunBinary;
using ::testing::HasSubstr;

class LocatorCliScopeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { server_ = new FakeLocatorServer(); }
  static void TearDownTestSuite() { delete server_; }

  // Runs `program --target <fake> args...`; it must succeed.
  static BinaryResult Run(const std::string& program,
                          const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target()};
    all.insert(all.end(), args.begin(), args.end());
    BinaryResult result = RunBinary(program, all);
    EXPECT_EQ(result.exit_code, 0) << result.err << result.out;
    return result;
  }

  // A file of x,y rows.
  std::string QueriesFile() const {
    const std::string path = dir_.path() + "/queries.csv";
    std::ofstream(path) << "x,y\n15.01,49.65\n15.02,49.66\n";
    return path;
  }

  static FakeLocatorServer* server_;
  test::ScratchDir dir_;
};

FakeLocatorServer* LocatorCliScopeTest::server_ = nullptr;

TEST_F(LocatorCliScopeTest, LocateSendsDatasetCrsAndInterpolation) {
  const BinaryResult result =
      Run(LOCATOR_PATH,
          {"--dataset", "terrain", "--crs", "EPSG:4326", "--interpolation",
           "natural-neighbor", "locate", "15.5", "49.25"});
  const v1::LocateRequest request = server_->last_locate();
  EXPECT_EQ(request.dataset(), "terrain");
  EXPECT_EQ(request.crs(), "EPSG:4326");
  EXPECT_EQ(request.interpolation(), v1::INTERPOLATION_NATURAL_NEIGHBOR);
  EXPECT_EQ(request.point().x(), 15.5);
  EXPECT_EQ(request.point().y(), 49.25);
  // FakeSurface: 1000 + x + 2y.
  EXPECT_THAT(result.out, HasSubstr("value        1114\n"));

  // Without the flags: the default dataset, its own coordinates, linear.
  Run(LOCATOR_PATH, {"locate", "1", "2"});
  EXPECT_EQ(server_->last_locate().dataset(), "");
  EXPECT_EQ(server_->last_locate().crs(), "");
  EXPECT_EQ(server_->last_locate().interpolation(),
            v1::INTERPOLATION_UNSPECIFIED);
}

TEST_F(LocatorCliScopeTest, BatchSendsThemWithEveryChunk) {
  Run(LOCATOR_PATH,
      {"batch", QueriesFile(), "--chunk", "1", "--dataset", "terrain", "--crs",
       "EPSG:4326", "--interpolation", "nearest"});
  const v1::LocateBatchRequest request = server_->last_locate_batch();
  EXPECT_EQ(request.dataset(), "terrain");
  EXPECT_EQ(request.crs(), "EPSG:4326");
  EXPECT_EQ(request.interpolation(), v1::INTERPOLATION_NEAREST);
  EXPECT_THAT(request.xs(), ::testing::ElementsAre(15.02));
}

TEST_F(LocatorCliScopeTest, AdminCommandsSendTheDataset) {
  Run(LOCATOR_PATH, {"--dataset", "bedrock", "stats"});
  EXPECT_EQ(server_->last_get_stats().dataset(), "bedrock");
  Run(LOCATOR_PATH, {"--dataset", "bedrock", "retune"});
  EXPECT_EQ(server_->last_retune().dataset(), "bedrock");
  const BinaryResult reload =
      Run(LOCATOR_PATH, {"--dataset", "bedrock", "reload", "bedrock.gpkg"});
  EXPECT_EQ(server_->last_reload().name(), "bedrock");
  EXPECT_EQ(server_->last_reload().spec(), "bedrock.gpkg");
  EXPECT_THAT(reload.out, HasSubstr("dataset      bedrock.gpkg\n"));
  Run(LOCATOR_PATH, {"reload"});
  EXPECT_EQ(server_->last_reload().name(), "");
  // Nor does it fill the deprecated field that `name` replaced.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  EXPECT_EQ(server_->last_reload().dataset(), "");
#pragma GCC diagnostic pop
}

TEST_F(LocatorCliScopeTest, DatasetsListsEveryDataset) {
  BinaryResult result = Run(LOCATOR_PATH, {"datasets"});
  EXPECT_EQ(result.out,
            "name     default  serving       points  triangles  crs\n"
            "terrain  *        yes           225     416        WGS 84 / UTM "
            "zone 33N (EPSG:32633)\n"
            "bedrock           no (loading)  -       -          -\n");
  result = Run(LOCATOR_PATH, {"datasets", "--json"});
  v1::ListDatasetsResponse response;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, &response).ok())
      << result.out;
  ASSERT_EQ(response.datasets_size(), 2);
  EXPECT_EQ(response.datasets(0).name(), "terrain");
  EXPECT_TRUE(response.datasets(0).is_default());
  EXPECT_EQ(response.datasets(0).stats().crs().epsg_code(), 32633u);
  EXPECT_FALSE(response.datasets(1).serving());
}

TEST_F(LocatorCliScopeTest, LoadDriverSendsDatasetAndCrsInEveryMode) {
  for (const char* mode : {"unary", "batch", "stream"}) {
    const BinaryResult result =
        Run(LOCATOR_LOAD_PATH,
            {"--mode", mode, "--workload", "file:" + QueriesFile(), "--queries",
             "4", "--concurrency", "1", "--batch-size", "2", "--dataset",
             "terrain", "--crs", "EPSG:4326", "--format", "json"});
    google::protobuf::Struct summary;
    ASSERT_TRUE(
        google::protobuf::util::JsonStringToMessage(result.out, &summary).ok())
        << result.out;
    EXPECT_EQ(summary.fields().at("dataset").string_value(), "terrain");
    EXPECT_EQ(summary.fields().at("crs").string_value(), "EPSG:4326");
  }
  EXPECT_EQ(server_->last_locate().dataset(), "terrain");
  EXPECT_EQ(server_->last_locate().crs(), "EPSG:4326");
  EXPECT_EQ(server_->last_locate_batch().dataset(), "terrain");
  EXPECT_EQ(server_->last_locate_batch().crs(), "EPSG:4326");
  const std::vector<v1::LocateRequest> streamed = server_->stream_requests();
  ASSERT_GE(streamed.size(), 4u);
  for (const v1::LocateRequest& request : streamed) {
    EXPECT_EQ(request.dataset(), "terrain");
    EXPECT_EQ(request.crs(), "EPSG:4326");
  }
}

TEST_F(LocatorCliScopeTest, LoadDriverReadsTheNamedDatasetsBox) {
  Run(LOCATOR_LOAD_PATH,
      {"--queries", "10", "--concurrency", "1", "--dataset", "bedrock"});
  EXPECT_EQ(server_->last_get_stats().dataset(), "bedrock");
  const v1::LocateRequest request = server_->last_locate();
  EXPECT_EQ(request.dataset(), "bedrock");
  EXPECT_EQ(request.crs(), "");
  // Generated in the dataset's bounding box.
  EXPECT_GE(request.point().x(), test::kFakeBox[0]);
  EXPECT_LE(request.point().x(), test::kFakeBox[2]);
  EXPECT_GE(request.point().y(), test::kFakeBox[1]);
  EXPECT_LE(request.point().y(), test::kFakeBox[3]);
}

TEST(LocatorLoadScopeTest, CrsNeedsAReplayedWorkload) {
  const BinaryResult result =
      RunBinary(LOCATOR_LOAD_PATH, {"--crs", "EPSG:4326", "--workload",
                                    "uniform", "--target", "127.0.0.1:1"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("--crs needs a --workload file:PATH"));
}

}  // namespace
}  // namespace locator
