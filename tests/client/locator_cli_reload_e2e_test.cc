// End to end: `locator reload` against a real locatord of its own (a reload
// changes what the server serves, so it does not share the CLI suite's).

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "locator/v1/locator.pb.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/server_process.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::RunBinary;
using test::ServerProcess;

class LocatorCliReloadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const Status status = ServerProcess::Start(
        LOCATORD_PATH,
        {"--dataset", "uniform:300:7", "--listen", "127.0.0.1:0",
         "--reload-dir", ::testing::TempDir()},
        &server_);
    ASSERT_TRUE(status.ok()) << status.ToString();
  }

  BinaryResult Locator(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target()};
    all.insert(all.end(), args.begin(), args.end());
    return RunBinary(LOCATOR_PATH, all);
  }

  std::unique_ptr<ServerProcess> server_;
};

TEST_F(LocatorCliReloadTest, ReloadPrintsTheNewDatasetAndGeneration) {
  BinaryResult result = Locator({"reload", "uniform:500:3"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("dataset      uniform:500:3"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("500 read"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("generation   2"), std::string::npos) << result.out;

  // Without a SPEC: the server's own dataset again, as JSON.
  result = Locator({"--json", "reload"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  v1::ReloadResponse response;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, &response).ok())
      << result.out;
  EXPECT_EQ(response.generation(), 3u);
  EXPECT_EQ(response.dataset().source(), "uniform:300:7");
  EXPECT_EQ(response.dataset().input_points(), 300u);

  result = Locator({"stats"});
  EXPECT_NE(result.out.find("generation   3"), std::string::npos) << result.out;
}

TEST_F(LocatorCliReloadTest, ABadDatasetIsAnRpcErrorWithFileAndLine) {
  const std::string path = ::testing::TempDir() + "locator_cli_reload_bad_" +
                           std::to_string(getpid()) + ".csv";
  std::ofstream(path) << "x,y\n1,2\n3,zz\n";
  const BinaryResult result = Locator({"reload", path});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err.rfind("error: INVALID_ARGUMENT: " + path + ":3", 0), 0u)
      << result.err;
  std::remove(path.c_str());
}

TEST_F(LocatorCliReloadTest, ReloadTakesOneSpecAtMost) {
  const BinaryResult result = Locator({"reload", "uniform:500:3", "extra"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("reload takes at most one SPEC"), std::string::npos)
      << result.err;
}

}  // namespace
}  // namespace locator
