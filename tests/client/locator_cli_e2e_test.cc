// End to end: the real `locator` binary against a real locatord serving a
// small dataset file. Checks exit codes (0 ok, 1 RPC error, 2 usage) and
// what each command prints.

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "client/locator_client.h"
#include "locator/dataset_sources.h"
#include "locator/v1/locator.pb.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/server_process.h"
#include "tests/testing/test_pki.h"

namespace locator {
namespace {

using test::BinaryResult;
using test::RunBinary;
using test::ServerProcess;

constexpr int kDatasetPoints = 300;
constexpr int kBatchRows = 25;

// A file of this process's own: ctest runs each test in a process of its
// own, several at once, and they must not rewrite each other's files.
std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "locator_cli_e2e_" +
                           std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

// x,y,z rows of uniform points in the unit square, z = x + 2y.
std::string DatasetCsv() {
  std::ostringstream csv;
  csv.precision(17);
  csv << "x,y,z\n";
  for (const Point2& p : GenerateUniform(kDatasetPoints, 7).points) {
    csv << p.x << "," << p.y << "," << p.x + 2 * p.y << "\n";
  }
  return csv.str();
}

// Splits `text` into lines (without the newlines).
std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> CsvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) {
    fields.push_back(field);
  }
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

class LocatorCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string dataset = WriteFile("dataset.csv", DatasetCsv());
    const Status status = ServerProcess::Start(
        LOCATORD_PATH, {"--dataset", dataset, "--listen", "127.0.0.1:0"},
        &server_);
    ASSERT_TRUE(status.ok()) << status.ToString();
  }
  static void TearDownTestSuite() { server_.reset(); }

  // Runs `locator --target <server> args...`.
  static BinaryResult Locator(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target()};
    all.insert(all.end(), args.begin(), args.end());
    return RunBinary(LOCATOR_PATH, all);
  }

  static std::unique_ptr<ServerProcess> server_;
};

std::unique_ptr<ServerProcess> LocatorCliTest::server_;

TEST_F(LocatorCliTest, LocatePrintsTheAnswer) {
  const BinaryResult result = Locator({"locate", "0.5", "0.5"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* label :
       {"type", "triangle", "vertices", "barycentric", "value", "cost"}) {
    EXPECT_NE(result.out.find(label), std::string::npos) << label;
  }
  EXPECT_NE(result.out.find("FACE"), std::string::npos) << result.out;
}

TEST_F(LocatorCliTest, LocateJsonIsOneParsableObject) {
  const BinaryResult result = Locator({"--json", "locate", "0.25", "0.75"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  v1::LocateResponse response;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, &response).ok())
      << result.out;
  EXPECT_EQ(response.type(), v1::LOCATION_TYPE_FACE);
  EXPECT_EQ(response.vertex_ids_size(), 3);
  ASSERT_TRUE(response.has_value());
  EXPECT_NEAR(response.value(), 0.25 + 2 * 0.75, 1e-9);  // z = x + 2y
}

TEST_F(LocatorCliTest, NegativeCoordinatesAreNotFlags) {
  const BinaryResult result = Locator({"locate", "-0.5", "-1e3"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("OUTSIDE_CONVEX_HULL"), std::string::npos);
}

TEST_F(LocatorCliTest, NonFiniteCoordinatesAreTheServersToReject) {
  const BinaryResult result = Locator({"locate", "nan", "0"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err.rfind("error: INVALID_ARGUMENT: ", 0), 0u) << result.err;
}

TEST_F(LocatorCliTest, UsageErrorsExitTwoWithUsage) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"locate", "1"},
                                             {"locate", "abc", "0"},
                                             {"bogus"},
                                             {},
                                             {"--bogus-flag", "stats"},
                                             {"--deadline-ms", "0", "stats"},
                                             {"stats", "extra"},
                                             {"batch"}}) {
    const BinaryResult result = Locator(args);
    EXPECT_EQ(result.exit_code, 2) << ::testing::PrintToString(args);
    EXPECT_NE(result.err.find("usage: locator"), std::string::npos)
        << result.err;
  }
}

TEST_F(LocatorCliTest, HelpPrintsUsageAndSucceeds) {
  const BinaryResult result = RunBinary(LOCATOR_PATH, {"--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("usage: locator"), std::string::npos);
}

TEST_F(LocatorCliTest, UnreachableServerIsAnRpcError) {
  const BinaryResult result =
      RunBinary(LOCATOR_PATH,
                {"--target", "127.0.0.1:1", "--deadline-ms", "2000", "stats"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err.rfind("error: UNAVAILABLE: ", 0), 0u) << result.err;
}

TEST_F(LocatorCliTest, BatchMatchesUnaryLocate) {
  std::ostringstream file;
  file.precision(17);
  file << "x,y\n# queries for the batch test\n";
  std::vector<Point2> queries;
  for (int i = 0; i < kBatchRows - 1; ++i) {
    queries.push_back(
        {0.05 + 0.9 * i / kBatchRows, 0.9 - 0.8 * i / kBatchRows});
  }
  // Outside the convex hull, with one nearest hull edge (a point nearest to
  // a hull vertex may be answered with either triangle beside it).
  queries.push_back({0.5, -1});
  for (const Point2& q : queries) file << q.x << " , " << q.y << "\n";

  // A chunk smaller than the file: the rows must come out in order anyway.
  const BinaryResult result =
      Locator({"--chunk", "7", "batch", WriteFile("queries.csv", file.str())});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<std::string> lines = Lines(result.out);
  ASSERT_EQ(lines.size(), kBatchRows + 1u) << result.out;
  EXPECT_EQ(lines[0], "x,y,type,triangle_id,v0,v1,v2,b0,b1,b2,value,cost");

  LocatorClient client(CreateLocatorChannel({.target = server_->target()}),
                       std::chrono::seconds(10));
  for (int i = 0; i < kBatchRows; ++i) {
    const std::vector<std::string> fields = CsvFields(lines[i + 1]);
    ASSERT_EQ(fields.size(), 12u) << lines[i + 1];
    v1::LocateResponse unary;
    ASSERT_TRUE(client.Locate(queries[i], &unary).ok());
    EXPECT_EQ(fields[3], std::to_string(unary.triangle_id())) << lines[i + 1];
  }
  EXPECT_EQ(CsvFields(lines.back())[2], "OUTSIDE_CONVEX_HULL");
  EXPECT_EQ(CsvFields(lines.back())[10], "");  // no value outside the hull
}

TEST_F(LocatorCliTest, BatchReportsTheBadLineOfItsFile) {
  const std::string path = WriteFile("bad.csv", "x,y\n1,2\n3,zz\n");
  const BinaryResult result = Locator({"batch", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(path + ":3: 'zz' is not a number"),
            std::string::npos)
      << result.err;
}

TEST_F(LocatorCliTest, StatsJsonHasThePointCount) {
  const BinaryResult result = Locator({"--json", "stats"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  v1::GetStatsResponse stats;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(result.out, &stats).ok())
      << result.out;
  EXPECT_EQ(stats.dataset().input_points(), uint64_t{kDatasetPoints});
  EXPECT_TRUE(stats.dataset().has_values());
  EXPECT_FALSE(stats.strategy().empty());
}

TEST_F(LocatorCliTest, StatsTextSummarizes) {
  const BinaryResult result = Locator({"stats"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* label :
       {"dataset", "points", "strategy", "serving", "tuning"}) {
    EXPECT_NE(result.out.find(label), std::string::npos) << label;
  }
  EXPECT_NE(result.out.find(std::to_string(kDatasetPoints) + " read"),
            std::string::npos)
      << result.out;
}

TEST_F(LocatorCliTest, RetunePrintsTheNewTuning) {
  const BinaryResult result = Locator({"retune"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.rfind("tuning", 0), 0u) << result.out;
}

TEST_F(LocatorCliTest, HealthIsServing) {
  const BinaryResult result = Locator({"health"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out, "SERVING\n");
}

TEST_F(LocatorCliTest, UnusableTokenFileIsAUsageErrorNamingIt) {
  const BinaryResult result =
      Locator({"--token-file", "/no/such/token", "stats"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--token-file '/no/such/token': cannot open"),
            std::string::npos)
      << result.err;
}

// A locatord with TLS and both tokens; the CLI sends what its flags say.
class LocatorCliSecurityTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ASSERT_TRUE(test::TestPki::Create(&pki_).ok());
    data_token_ = WriteFile("data_token", "cli-data-token\n");
    admin_token_ = WriteFile("admin_token", "cli-admin-token\n");
    std::vector<std::string> args = {
        "--dataset",    "uniform:500:1", "--listen",           "127.0.0.1:0",
        "--token-file", data_token_,     "--admin-token-file", admin_token_};
    const std::vector<std::string> tls = pki_->ServerFlags(/*mutual=*/true);
    args.insert(args.end(), tls.begin(), tls.end());
    ChannelSecurity security = pki_->ClientSecurity(/*client_cert=*/true);
    security.bearer_token = "cli-data-token";
    const Status status =
        ServerProcess::Start(LOCATORD_PATH, args, &server_, security);
    ASSERT_TRUE(status.ok()) << status.ToString();
  }
  static void TearDownTestSuite() {
    server_.reset();
    pki_.reset();
  }

  // `locator --target <server> <TLS flags> args...`.
  static BinaryResult Locator(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--target", server_->target(),
                                    "--tls-server-name", "localhost"};
    const std::vector<std::string> tls =
        pki_->ClientFlags(/*client_cert=*/true);
    all.insert(all.end(), tls.begin(), tls.end());
    all.insert(all.end(), args.begin(), args.end());
    return RunBinary(LOCATOR_PATH, all);
  }

  static std::unique_ptr<test::TestPki> pki_;
  static std::unique_ptr<ServerProcess> server_;
  static std::string data_token_;
  static std::string admin_token_;
};

std::unique_ptr<test::TestPki> LocatorCliSecurityTest::pki_;
std::unique_ptr<ServerProcess> LocatorCliSecurityTest::server_;
std::string LocatorCliSecurityTest::data_token_;
std::string LocatorCliSecurityTest::admin_token_;

TEST_F(LocatorCliSecurityTest, TokenFileIsSentOnEveryCall) {
  const BinaryResult stats = Locator({"--token-file", data_token_, "stats"});
  EXPECT_EQ(stats.exit_code, 0) << stats.err;
  const BinaryResult anonymous = Locator({"locate", "0.5", "0.5"});
  EXPECT_EQ(anonymous.exit_code, 1);
  EXPECT_EQ(anonymous.err.rfind("error: UNAUTHENTICATED: ", 0), 0u)
      << anonymous.err;
  const BinaryResult retune = Locator({"--token-file", data_token_, "retune"});
  EXPECT_EQ(retune.exit_code, 1);
  EXPECT_EQ(retune.err.rfind("error: PERMISSION_DENIED: ", 0), 0u)
      << retune.err;
  EXPECT_EQ(Locator({"--token-file", admin_token_, "retune"}).exit_code, 0);
  // Health is open to probes without a token.
  EXPECT_EQ(Locator({"health"}).exit_code, 0);
}

TEST_F(LocatorCliSecurityTest, PlaintextToTlsServerIsUnavailable) {
  const BinaryResult result =
      RunBinary(LOCATOR_PATH, {"--target", server_->target(), "--token-file",
                               data_token_, "--deadline-ms", "5000", "stats"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err.rfind("error: UNAVAILABLE: ", 0), 0u) << result.err;
}

TEST_F(LocatorCliSecurityTest, LoadDriverSendsTokenOverMutualTls) {
  std::vector<std::string> args = {"--target",      server_->target(),
                                   "--token-file",  data_token_,
                                   "--queries",     "2000",
                                   "--concurrency", "4"};
  const std::vector<std::string> tls = pki_->ClientFlags(/*client_cert=*/true);
  args.insert(args.end(), tls.begin(), tls.end());
  // Exit code 0: every call (GetStats for the bounding box, then the load)
  // succeeded.
  const BinaryResult result = RunBinary(LOCATOR_LOAD_PATH, args);
  EXPECT_EQ(result.exit_code, 0) << result.err << result.out;
  // Without the token, every call fails.
  args.erase(args.begin() + 2, args.begin() + 4);
  EXPECT_NE(RunBinary(LOCATOR_LOAD_PATH, args).exit_code, 0);
}

}  // namespace
}  // namespace locator
