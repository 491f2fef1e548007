// The HTTP/JSON API end to end, against the real locatord with two named
// datasets: :locate and :locateBatch answer exactly what gRPC answers for
// the same request (the parsed protos compared field by field, but for the
// work each call took: the walk visits a triangle's edges in random order,
// so two calls for one point may visit different faces), ListDatasets
// likewise; every error is the gRPC status as HTTP status plus an
// {"code", "status", "message"} body; tokens are the gRPC ones; CORS answers
// allowed origins only; /metrics labels every engine series with its
// dataset; the status API takes ?dataset=.

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/http/http_test_client.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/json_value.h"
#include "tests/server/http/prometheus_text.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using Code = grpc::StatusCode;

constexpr char kAllowedOrigin[] = "http://maps.example.org";
constexpr int kMaxBatchPoints = 5000;
constexpr size_t kMaxBodyBytes = 256 * 1024;
constexpr char kDataToken[] = "data-token-1234";

class JsonApiTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dataset_ = new TestDatasetFile();
    const Status started = LocatordWithHttp::Start(
        "terrain=" + dataset_->path(),
        {"--dataset", "bedrock=uniform:3000:7", "--max-batch-points",
         std::to_string(kMaxBatchPoints), "--http-max-body-bytes",
         std::to_string(kMaxBodyBytes), "--http-cors-origin", kAllowedOrigin},
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
    ASSERT_TRUE(server_->WaitUntilServes("bedrock").ok());
  }
  static void TearDownTestSuite() {
    server_.reset();
    delete dataset_;
  }
  void SetUp() override {
    ASSERT_NE(server_, nullptr);
    stub_ = server_->NewStub();
  }
  static int port() { return server_->http_port(); }

  static TestDatasetFile* dataset_;
  static std::unique_ptr<LocatordWithHttp> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

TestDatasetFile* JsonApiTest::dataset_ = nullptr;
std::unique_ptr<LocatordWithHttp> JsonApiTest::server_;

TEST_F(JsonApiTest, LocateAnswersWhatGrpcAnswers) {
  const std::vector<Point2> queries = TestQueries();
  for (size_t i = 0; i < queries.size(); i += 50) {
    for (const char* dataset : {"terrain", "bedrock"}) {
      const v1::LocateRequest request = LocateRequestFor(queries[i]);
      const HttpReply reply =
          Post(port(), std::string("/v1/datasets/") + dataset + ":locate",
               ToJson(request));
      ASSERT_EQ(reply.status, 200u) << reply.body;
      EXPECT_EQ(reply.headers.at("content-type"), "application/json");
      v1::LocateResponse expected;
      ASSERT_TRUE(LocateOne(*stub_, queries[i], &expected, dataset).ok());
      v1::LocateResponse answer = FromJson<v1::LocateResponse>(reply.body);
      EXPECT_GT(answer.cost().total(), 0u);
      answer.clear_cost();
      expected.clear_cost();
      EXPECT_TRUE(SameProto(answer, expected)) << dataset << " query " << i;
    }
  }
}

TEST_F(JsonApiTest, LocateBatchAnswersWhatGrpcAnswers) {
  const std::vector<Point2> all = TestQueries();
  const std::vector<Point2> queries(all.begin(), all.begin() + 2000);
  v1::LocateBatchRequest request = BatchRequestFor(queries);
  const HttpReply reply =
      Post(port(), "/v1/datasets/terrain:locateBatch", ToJson(request));
  ASSERT_EQ(reply.status, 200u) << reply.body.substr(0, 300);
  request.set_dataset("terrain");
  grpc::ClientContext context;
  v1::LocateBatchResponse expected;
  ASSERT_TRUE(stub_->LocateBatch(&context, request, &expected).ok());
  auto answer = FromJson<v1::LocateBatchResponse>(reply.body);
  EXPECT_EQ(answer.types_size(), 2000);
  EXPECT_EQ(answer.costs_size(), 2000);
  EXPECT_GT(answer.total_cost(), 0u);
  for (v1::LocateBatchResponse* response : {&answer, &expected}) {
    response->clear_costs();
    response->clear_total_cost();
  }
  EXPECT_TRUE(SameProto(answer, expected));
}

TEST_F(JsonApiTest, ListDatasetsAnswersWhatGrpcAnswers) {
  HttpReply reply;
  ASSERT_TRUE(HttpGet(port(), "/v1/datasets", &reply).ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  grpc::ClientContext context;
  v1::ListDatasetsResponse expected;
  ASSERT_TRUE(stub_->ListDatasets(&context, {}, &expected).ok());
  const auto answer = FromJson<v1::ListDatasetsResponse>(reply.body);
  EXPECT_TRUE(SameProto(answer, expected));
  ASSERT_EQ(answer.datasets_size(), 2);
  EXPECT_EQ(answer.datasets(1).name(), "bedrock");
}

TEST_F(JsonApiTest, TopologyAnswersWhatGrpcAnswers) {
  HttpReply reply;
  ASSERT_TRUE(HttpGet(port(), "/v1/datasets/bedrock:topology", &reply).ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  grpc::ClientContext context;
  v1::GetTopologyRequest request;
  request.set_dataset("bedrock");
  v1::GetTopologyResponse expected;
  ASSERT_TRUE(stub_->GetTopology(&context, request, &expected).ok());
  const auto answer = FromJson<v1::GetTopologyResponse>(reply.body);
  EXPECT_TRUE(SameProto(answer, expected));
  // Not a tile set: one shard, this server, serving all of it.
  EXPECT_FALSE(answer.tiled());
  EXPECT_TRUE(answer.complete());
  EXPECT_EQ(answer.shards_size(), 1);
}

TEST_F(JsonApiTest, TheBodyMayUseEitherFieldNameAndNameThePathsDataset) {
  const HttpReply camel = Post(port(), "/v1/datasets/bedrock:locateBatch",
                               R"({"xs": [0.5], "ys": [0.5],
                                   "includeVertexIds": true,
                                   "dataset": "bedrock"})");
  ASSERT_EQ(camel.status, 200u) << camel.body;
  EXPECT_EQ(FromJson<v1::LocateBatchResponse>(camel.body).vertex_ids_size(), 3);
}

// One row of the error table: what is sent and what must come back.
struct ErrorRow {
  std::string name;
  std::string method;
  std::string target;
  std::string body;
  unsigned http;
  Code code;
  std::string message;
  // Of a POST; "" sends none.
  std::string content_type = "application/json";
};

void PrintTo(const ErrorRow& row, std::ostream* out) {
  *out << row.method << " " << row.target.substr(0, 80);
}

std::string BatchOf(size_t points) {
  std::ostringstream body;
  body << R"({"xs": [)";
  for (size_t i = 0; i < points; ++i) body << (i ? "," : "") << 0.5;
  body << R"(], "ys": [)";
  for (size_t i = 0; i < points; ++i) body << (i ? "," : "") << 0.25;
  body << "]}";
  return body.str();
}

// No error message is longer: each quotes what it was sent short.
constexpr size_t kMaxMessageBytes = 300;

std::vector<ErrorRow> ErrorRows() {
  const std::string locate = "/v1/datasets/terrain:locate";
  const std::string long_name(6000, 'w');
  return {
      {"MalformedJson", "POST", locate, R"({"point": {"x": 1,)", 400,
       Code::INVALID_ARGUMENT,
       "the body is not a locator.v1.LocateRequest in JSON: "},
      {"UnknownField", "POST", locate, R"({"pont": {"x": 1, "y": 2}})", 400,
       Code::INVALID_ARGUMENT, "pont"},
      {"UnknownDataset", "POST", "/v1/datasets/lava:locate", "{}", 404,
       Code::NOT_FOUND,
       "unknown dataset 'lava'; this server has: terrain (default), bedrock"},
      {"BodyNamesAnotherDataset", "POST", locate,
       R"({"point": {"x": 1, "y": 2}, "dataset": "bedrock"})", 400,
       Code::INVALID_ARGUMENT,
       "the body names dataset 'bedrock' but the path names 'terrain'"},
      {"NaN", "POST", locate, R"({"point": {"x": "NaN", "y": 2}})", 400,
       Code::INVALID_ARGUMENT, "non-finite coordinate"},
      {"Infinity", "POST", locate, R"({"point": {"x": 1, "y": "-Infinity"}})",
       400, Code::INVALID_ARGUMENT, "non-finite coordinate"},
      {"MissingPoint", "POST", locate, "{}", 400, Code::INVALID_ARGUMENT,
       "point is required"},
      {"EmptyBody", "POST", locate, "", 400, Code::INVALID_ARGUMENT,
       "point is required"},
      {"BatchNaN", "POST", "/v1/datasets/terrain:locateBatch",
       R"({"xs": [1, 2], "ys": [1, "NaN"]})", 400, Code::INVALID_ARGUMENT,
       "point 1 has a non-finite coordinate"},
      {"BatchColumns", "POST", "/v1/datasets/terrain:locateBatch",
       R"({"xs": [1, 2], "ys": [1]})", 400, Code::INVALID_ARGUMENT,
       "xs has 2 values but ys has 1"},
      {"OversizedBatch", "POST", "/v1/datasets/bedrock:locateBatch",
       BatchOf(kMaxBatchPoints + 1), 429, Code::RESOURCE_EXHAUSTED,
       "batch of 5001 points exceeds this server's limit of 5000 points"},
      {"OversizedBody", "POST", "/v1/datasets/bedrock:locateBatch",
       BatchOf(kMaxBodyBytes / 8), 413, Code::RESOURCE_EXHAUSTED,
       "the request body is larger than this server's limit of 262144 bytes "
       "(--http-max-body-bytes)"},
      {"UnknownRoute", "GET", "/v1/nope", "", 404, Code::NOT_FOUND,
       "no API method 'GET /v1/nope'"},
      {"UnknownMethodOfADataset", "POST", "/v1/datasets/terrain:warp", "{}",
       404, Code::NOT_FOUND, "no API method 'POST /v1/datasets/terrain:warp'"},
      {"GetOfAPostMethod", "GET", locate, "", 405, Code::UNIMPLEMENTED,
       "'GET' is not allowed on '/v1/datasets/terrain:locate'; use POST"},
      {"PostOfAGetMethod", "POST", "/v1/datasets", "{}", 405,
       Code::UNIMPLEMENTED, "'POST' is not allowed on '/v1/datasets'; use GET"},
      {"PostOfTopology", "POST", "/v1/datasets/terrain:topology", "{}", 405,
       Code::UNIMPLEMENTED,
       "'POST' is not allowed on '/v1/datasets/terrain:topology'; use GET"},
      {"TopologyOfAnUnknownDataset", "GET", "/v1/datasets/lava:topology", "",
       404, Code::NOT_FOUND,
       "unknown dataset 'lava'; this server has: terrain (default), bedrock"},
      // What the client sent is quoted short, however long (within the
      // 8 KiB header and the body limit).
      {"LongUnknownRoute", "GET", "/v1/" + long_name, "", 404, Code::NOT_FOUND,
       "no API method 'GET /v1/" + long_name.substr(0, 72) +
           "...' (6008 bytes)"},
      {"LongPathOfAPostMethod", "GET", "/v1/datasets/" + long_name + ":locate",
       "", 405, Code::UNIMPLEMENTED,
       "'GET' is not allowed on '/v1/datasets/" + long_name.substr(0, 67) +
           "...' (6020 bytes); use POST"},
      {"BodyNamesALongDataset", "POST", locate,
       R"({"point": {"x": 1, "y": 2}, "dataset": ")" + long_name + R"("})", 400,
       Code::INVALID_ARGUMENT,
       "the body names dataset '" + long_name.substr(0, 80) +
           "...' (6000 bytes) but the path names 'terrain'"},
      {"LongUnknownField", "POST", locate, R"({")" + long_name + R"(": 1})",
       400, Code::INVALID_ARGUMENT,
       "the body is not a locator.v1.LocateRequest in JSON: "},
      {"LongEnumValue", "POST", locate,
       R"({"point": {"x": 1, "y": 2}, "interpolation": ")" + long_name +
           R"("})",
       400, Code::INVALID_ARGUMENT, "(interpolation): invalid value"},
      // What a page of another origin can POST without a CORS preflight.
      {"TextPlainPost", "POST", locate, R"({"point": {"x": 1, "y": 2}})", 415,
       Code::INVALID_ARGUMENT,
       "a POST to the API must have Content-Type: application/json",
       "text/plain"},
      {"FormPost", "POST", locate, R"({"point": {"x": 1, "y": 2}})", 415,
       Code::INVALID_ARGUMENT, "Content-Type: application/json",
       "application/x-www-form-urlencoded"},
      {"PostWithoutContentType", "POST", locate,
       R"({"point": {"x": 1, "y": 2}})", 415, Code::INVALID_ARGUMENT,
       "Content-Type: application/json", ""},
      {"JsonWithCharsetIsJson", "POST", locate, "{}", 400,
       Code::INVALID_ARGUMENT, "point is required",
       "Application/JSON; charset=utf-8"},
  };
}

class JsonApiErrorTest : public JsonApiTest,
                         public ::testing::WithParamInterface<ErrorRow> {};

TEST_P(JsonApiErrorTest, AnswersTheGrpcStatusAsHttp) {
  const ErrorRow& row = GetParam();
  HttpHeaders headers;
  if (row.method == "POST" && !row.content_type.empty()) {
    headers.emplace_back("Content-Type", row.content_type);
  }
  HttpReply reply;
  ASSERT_TRUE(
      SendHttp(port(), row.method, row.target, &reply, row.body, headers).ok());
  ExpectError(reply, row.http, row.code, row.message);
  JsonValue error;
  ASSERT_TRUE(ParseJson(reply.body, &error).ok());
  EXPECT_LE(error["message"].string().size(), kMaxMessageBytes)
      << reply.body.substr(0, 300);
  if (row.http == 405) {
    EXPECT_EQ(reply.headers["allow"], row.method == "GET" ? "POST" : "GET");
  }
  // The server still answers.
  const HttpReply after =
      Post(port(), "/v1/datasets/terrain:locate", R"({"point": {"x": 5.5,
                                                               "y": 5.5}})");
  EXPECT_EQ(after.status, 200u) << after.body;
}

INSTANTIATE_TEST_SUITE_P(Rows, JsonApiErrorTest,
                         ::testing::ValuesIn(ErrorRows()),
                         [](const ::testing::TestParamInfo<ErrorRow>& info) {
                           return info.param.name;
                         });

TEST_F(JsonApiTest, CorsAnswersAllowedOriginsOnly) {
  const HttpHeaders preflight_of = {
      {"Origin", kAllowedOrigin},
      {"Access-Control-Request-Method", "POST"},
      {"Access-Control-Request-Headers", "authorization, content-type"}};
  HttpReply preflight;
  ASSERT_TRUE(SendHttp(port(), "OPTIONS", "/v1/datasets/terrain:locate",
                       &preflight, "", preflight_of)
                  .ok());
  EXPECT_EQ(preflight.status, 204u);
  EXPECT_EQ(preflight.headers["access-control-allow-origin"], kAllowedOrigin);
  EXPECT_EQ(preflight.headers["access-control-allow-methods"],
            "GET, POST, OPTIONS");
  EXPECT_EQ(preflight.headers["access-control-allow-headers"],
            "Authorization, Content-Type");
  EXPECT_EQ(preflight.headers["vary"], "Origin");

  const HttpReply allowed =
      Post(port(), "/v1/datasets/terrain:locate",
           R"({"point": {"x": 5.5, "y": 5.5}})", {{"Origin", kAllowedOrigin}});
  EXPECT_EQ(allowed.status, 200u);
  EXPECT_EQ(allowed.headers.at("access-control-allow-origin"), kAllowedOrigin);
  // The status API too (the web example reads /api/edges).
  HttpReply edges;
  ASSERT_TRUE(SendHttp(port(), "GET", "/api/edges?dataset=bedrock", &edges, "",
                       {{"Origin", kAllowedOrigin}})
                  .ok());
  EXPECT_EQ(edges.headers["access-control-allow-origin"], kAllowedOrigin);

  // Another origin: no CORS header on answers, 403 to its preflight.
  const std::string other = "http://evil.example.org";
  const HttpReply denied =
      Post(port(), "/v1/datasets/terrain:locate",
           R"({"point": {"x": 5.5, "y": 5.5}})", {{"Origin", other}});
  EXPECT_EQ(denied.status, 200u);
  EXPECT_EQ(denied.headers.count("access-control-allow-origin"), 0u);
  HttpReply refused;
  ASSERT_TRUE(
      SendHttp(port(), "OPTIONS", "/v1/datasets/terrain:locate", &refused, "",
               {{"Origin", other}, {"Access-Control-Request-Method", "POST"}})
          .ok());
  ExpectError(refused, 403, Code::PERMISSION_DENIED,
              "origin 'http://evil.example.org' may not call this server");
  EXPECT_EQ(refused.headers.count("access-control-allow-origin"), 0u);
}

TEST_F(JsonApiTest, EngineMetricsAndTheStatusApiAreLabelledByDataset) {
  v1::LocateResponse located;
  for (int i = 0; i < 7; ++i) {
    ASSERT_TRUE(LocateOne(*stub_, {0.5, 0.5}, &located, "bedrock").ok());
  }
  const v1::GetStatsResponse bedrock = GetStats(*stub_, "bedrock");
  const v1::GetStatsResponse terrain = GetStats(*stub_, "terrain");
  HttpReply reply;
  ASSERT_TRUE(HttpGet(port(), "/metrics", &reply).ok());
  PrometheusText metrics;
  ASSERT_TRUE(ParsePrometheusText(reply.body, &metrics).ok());
  for (const char* name : {"terrain", "bedrock"}) {
    EXPECT_EQ(metrics.Value("locator_engine_loaded", {{"dataset", name}}), 1)
        << name;
  }
  EXPECT_EQ(metrics.Value("locator_queries_total", {{"dataset", "bedrock"}}),
            bedrock.queries_served());
  EXPECT_EQ(metrics.Value("locator_dataset_vertices", {{"dataset", "bedrock"}}),
            3000);
  EXPECT_EQ(
      metrics.Value("locator_triangulation_bytes", {{"dataset", "terrain"}}),
      terrain.memory().triangulation_bytes());
  EXPECT_EQ(metrics.Value("locator_tuning_bytes", {{"dataset", "bedrock"}}),
            bedrock.memory().tuning_bytes());
  // Every engine series has the label.
  for (const PrometheusSample& sample : metrics.samples) {
    if (sample.name.starts_with("locator_rpc_") ||
        sample.name.starts_with("locator_http_")) {
      continue;
    }
    EXPECT_EQ(sample.labels.count("dataset"), 1u) << sample.name;
  }

  const JsonValue stats = GetJson(port(), "/api/stats?dataset=bedrock");
  EXPECT_EQ(stats["dataset"]["name"].string(), "bedrock");
  EXPECT_EQ(GetJson(port(), "/api/stats")["dataset"]["name"].string(),
            "terrain");
  HttpReply unknown;
  ASSERT_TRUE(HttpGet(port(), "/api/history?dataset=lava", &unknown).ok());
  ExpectError(unknown, 404, Code::NOT_FOUND, "unknown dataset 'lava'");
}

TEST(JsonApiTokenTest, TheGrpcTokensAndScopesApply) {
  ScratchDir dir;
  const std::string token_file = dir.path() + "/token";
  std::ofstream(token_file) << kDataToken << "\n";
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start("uniform:2000:1",
                                      {"--token-file", token_file, "--redact"},
                                      &server, kDataToken)
                  .ok());
  const int port = server->http_port();
  const std::string locate = "/v1/datasets/default:locate";
  const std::string body = R"({"point": {"x": 0.5, "y": 0.5}})";
  const std::string no_token =
      "expected 'authorization: Bearer <token>' (gRPC metadata or HTTP "
      "header)";
  ExpectError(Post(port, locate, body), 401, Code::UNAUTHENTICATED, no_token);
  ExpectError(Post(port, locate, body, {{"Authorization", "Bearer guess"}}),
              403, Code::PERMISSION_DENIED, "the bearer token is not accepted");
  const HttpHeaders token = {
      {"Authorization", std::string("Bearer ") + kDataToken}};
  EXPECT_EQ(Post(port, locate, body, token).status, 200u);
  HttpReply list;
  ASSERT_TRUE(SendHttp(port, "GET", "/v1/datasets", &list, "", token).ok());
  ASSERT_EQ(list.status, 200u);
  // --redact applies to the API as to every output.
  const auto datasets = FromJson<v1::ListDatasetsResponse>(list.body);
  ASSERT_EQ(datasets.datasets_size(), 1);
  EXPECT_EQ(datasets.datasets(0).stats().source(), "");
  EXPECT_EQ(datasets.datasets(0).stats().input_points(), 2000u);

  // The status API's statistics and edges want the token as GetStats does;
  // the history (counts and costs only) and /metrics do not.
  for (const char* path : {"/api/stats", "/api/edges"}) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port, path, &reply).ok());
    ExpectError(reply, 401, Code::UNAUTHENTICATED, no_token);
    ASSERT_TRUE(SendHttp(port, "GET", path, &reply, "",
                         {{"Authorization", "Bearer guess"}})
                    .ok());
    ExpectError(reply, 403, Code::PERMISSION_DENIED,
                "the bearer token is not accepted");
    ASSERT_TRUE(SendHttp(port, "GET", path, &reply, "", token).ok());
    EXPECT_EQ(reply.status, 200u) << path;
  }
  for (const char* path : {"/api/history", "/metrics"}) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port, path, &reply).ok());
    EXPECT_EQ(reply.status, 200u) << path;
  }
}

TEST(JsonApiTokenTest, PublicStatusOpensTheStatusApiOnly) {
  ScratchDir dir;
  const std::string token_file = dir.path() + "/token";
  std::ofstream(token_file) << kDataToken << "\n";
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start(
                  "uniform:2000:1",
                  {"--token-file", token_file, "--http-public-status"}, &server)
                  .ok());
  const int port = server->http_port();
  for (const char* path : {"/api/stats", "/api/edges"}) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(port, path, &reply).ok());
    EXPECT_EQ(reply.status, 200u) << path;
  }
  ExpectError(Post(port, "/v1/datasets/default:locate",
                   R"({"point": {"x": 0.5, "y": 0.5}})"),
              401, Code::UNAUTHENTICATED, "Bearer <token>");
}

TEST(JsonApiDeadlineTest, ABatchPastTheServersDefaultDeadlineIs504) {
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start(
                  "uniform:20000:1",
                  {"--default-deadline-ms", "1", "--threads", "1"}, &server)
                  .ok());
  ExpectError(Post(server->http_port(), "/v1/datasets/default:locateBatch",
                   BatchOf(200000)),
              504, Code::DEADLINE_EXCEEDED,
              "(the server's default of 1 ms; the call set no deadline)");
}

}  // namespace
}  // namespace locator::test

namespace locator::test {
namespace {

TEST(JsonApiGridLimitTest, AGridOverTheHttpLimitNamesTheFlag) {
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start("uniform:2000:1",
                                      {"--http-max-grid-cells", "100"}, &server)
                  .ok());
  const std::string grid = "/v1/datasets/default:grid";
  const HttpReply fits = Post(server->http_port(), grid,
                              R"({"box": {"min_x": 0.1, "min_y": 0.1,
                                          "max_x": 0.9, "max_y": 0.9},
                                  "width": 10, "height": 10})");
  ASSERT_EQ(fits.status, 200u) << fits.body;
  const auto answer = FromJson<v1::GridResponse>(fits.body);
  EXPECT_EQ(answer.values_size(), 100);
  EXPECT_EQ(answer.rows(), 10u);
  EXPECT_EQ(answer.header().width(), 10u);
  ExpectError(Post(server->http_port(), grid,
                   R"({"box": {"min_x": 0.1, "min_y": 0.1,
                               "max_x": 0.9, "max_y": 0.9},
                       "width": 11, "height": 10})"),
              429, Code::RESOURCE_EXHAUSTED,
              "a grid of 11 x 10 = 110 cells exceeds this server's limit of "
              "100 cells per request (--http-max-grid-cells");
}

TEST(JsonApiDeadlineTest, AGridPastTheServersDefaultDeadlineIs504) {
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start("uniform:20000:1",
                                      {"--default-deadline-ms", "1"}, &server)
                  .ok());
  ExpectError(Post(server->http_port(), "/v1/datasets/default:grid",
                   R"({"box": {"min_x": 0, "min_y": 0, "max_x": 1,
                               "max_y": 1},
                       "width": 1000, "height": 1000,
                       "interpolation": "INTERPOLATION_NATURAL_NEIGHBOR"})"),
              504, Code::DEADLINE_EXCEEDED,
              "(the server's default of 1 ms; the call set no deadline)");
}

}  // namespace
}  // namespace locator::test
