// locatord's HTTP side end to end: /metrics counts exactly the gRPC calls
// the test makes and parses as strict Prometheus text; /api/stats is
// GetStats's answer as proto JSON, /api/history and /api/edges are valid
// JSON agreeing with the traffic; with --redact no HTTP output shows a
// server path; unknown paths, other methods and an address in use are
// refused.

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "client/health_check.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/http_test_client.h"
#include "tests/server/http/prometheus_text.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr char kDataset[] = "uniform:20000:1";
constexpr int kLocateCalls = 137;
constexpr int kInvalidCalls = 3;
constexpr int kBatchPoints = 50;

const std::map<std::string, std::string> kLocate = {
    {"service", "locator.v1.Locator"}, {"method", "Locate"}};

std::map<std::string, std::string> With(std::map<std::string, std::string> a,
                                        const std::string& code) {
  a["code"] = code;
  return a;
}

class StatusHttpTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const Status started = LocatordWithHttp::Start(kDataset, {}, &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
    auto stub = server_->NewStub();
    for (int i = 0; i < kLocateCalls; ++i) {
      v1::LocateResponse response;
      const Point2 q{(i % 10) / 10.0 + 0.01, (i / 10) / 14.0 + 0.01};
      const grpc::Status s = test::LocateOne(*stub, q, &response);
      ASSERT_TRUE(s.ok()) << s.error_message();
      cost_sum_ += response.cost().total();
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < kInvalidCalls; ++i) {
      v1::LocateResponse response;
      EXPECT_EQ(test::LocateOne(*stub, {nan, 0.5}, &response).error_code(),
                grpc::StatusCode::INVALID_ARGUMENT);
    }
    v1::LocateBatchRequest batch;
    for (int i = 0; i < kBatchPoints; ++i) {
      batch.add_xs(0.5 + i / 200.0);
      batch.add_ys(0.25);
    }
    grpc::ClientContext context;
    v1::LocateBatchResponse answers;
    ASSERT_TRUE(stub->LocateBatch(&context, batch, &answers).ok());
    cost_sum_ += answers.total_cost();
    // Another service than locator.v1's.
    HealthChecker health(grpc::CreateChannel(
        server_->grpc_target(), grpc::InsecureChannelCredentials()));
    grpc::ClientContext health_context;
    HealthStatus serving = HealthStatus::kUnknown;
    ASSERT_TRUE(health.Check(&health_context, "", &serving).ok());
  }
  static void TearDownTestSuite() { server_.reset(); }

  void SetUp() override { ASSERT_NE(server_, nullptr); }

  static PrometheusText Metrics() {
    HttpReply reply;
    EXPECT_TRUE(HttpGet(server_->http_port(), "/metrics", &reply).ok());
    EXPECT_EQ(reply.status, 200u);
    EXPECT_EQ(reply.headers["content-type"],
              "text/plain; version=0.0.4; charset=utf-8");
    PrometheusText metrics;
    const Status parsed = ParsePrometheusText(reply.body, &metrics);
    EXPECT_TRUE(parsed.ok()) << parsed.ToString();
    return metrics;
  }

  static std::unique_ptr<LocatordWithHttp> server_;
  static uint64_t cost_sum_;
};

std::unique_ptr<LocatordWithHttp> StatusHttpTest::server_;
uint64_t StatusHttpTest::cost_sum_ = 0;

TEST_F(StatusHttpTest, RpcCountersMatchTheCallsMade) {
  const PrometheusText m = Metrics();
  EXPECT_EQ(m.types.at("locator_rpc_requests_total"), "counter");
  EXPECT_EQ(m.types.at("locator_rpc_duration_seconds"), "histogram");
  EXPECT_EQ(m.Value("locator_rpc_requests_total", With(kLocate, "OK")),
            kLocateCalls);
  EXPECT_EQ(
      m.Value("locator_rpc_requests_total", With(kLocate, "INVALID_ARGUMENT")),
      kInvalidCalls);
  EXPECT_EQ(
      m.Value("locator_rpc_errors_total", With(kLocate, "INVALID_ARGUMENT")),
      kInvalidCalls);
  EXPECT_EQ(m.Value("locator_rpc_errors_total", With(kLocate, "OK")),
            std::nullopt);
  EXPECT_EQ(m.Value("locator_rpc_requests_total",
                    {{"method", "LocateBatch"}, {"code", "OK"}}),
            1);
  EXPECT_EQ(m.Value("locator_rpc_requests_total",
                    {{"service", "grpc.health.v1.Health"},
                     {"method", "Check"},
                     {"code", "OK"}}),
            1);
  EXPECT_EQ(m.Value("locator_rpc_duration_seconds_count", kLocate),
            kLocateCalls + kInvalidCalls);
  EXPECT_EQ(m.Value("locator_rpc_duration_seconds_bucket",
                    {{"method", "Locate"}, {"le", "+Inf"}}),
            kLocateCalls + kInvalidCalls);
}

TEST_F(StatusHttpTest, EngineMetricsMatchTheQueriesLocated) {
  const PrometheusText m = Metrics();
  const double located = kLocateCalls + kBatchPoints;
  EXPECT_EQ(m.Value("locator_engine_loaded"), 1);
  EXPECT_EQ(m.Value("locator_queries_total"), located);
  EXPECT_EQ(m.Value("locator_query_cost_total"), double(cost_sum_));
  EXPECT_EQ(m.Value("locator_walk_faces_count"), located);
  EXPECT_EQ(m.Value("locator_walk_faces_bucket", {{"le", "+Inf"}}), located);
  EXPECT_EQ(*m.Value("locator_hot_region_queries_total") +
                *m.Value("locator_fallback_queries_total"),
            located);
  EXPECT_GE(m.Value("locator_snapshot_version"), 1);
  EXPECT_GT(m.Value("locator_triangulation_bytes"), 1e6);
  EXPECT_GT(m.Value("locator_tuning_bytes"), 0);
  EXPECT_EQ(m.Value("locator_dataset_vertices"), 20000);
  // Buckets are cumulative.
  double previous = 0;
  for (const PrometheusSample& s : m.samples) {
    if (s.name != "locator_walk_faces_bucket") continue;
    EXPECT_GE(s.value, previous) << s.labels.at("le");
    previous = s.value;
  }
}

// Proto JSON writes 64-bit integers as strings.
uint64_t Uint64(const JsonValue& value) { return std::stoull(value.string()); }

TEST_F(StatusHttpTest, StatsJsonIsGetStatsAsProtoJson) {
  const JsonValue stats = GetJson(server_->http_port(), "/api/stats");
  ASSERT_FALSE(stats.is_null());
  EXPECT_EQ(stats["strategy"].string(), "self-tuning");
  EXPECT_EQ(stats["dataset"]["source"].string(), kDataset);
  EXPECT_EQ(Uint64(stats["dataset"]["vertices"]), 20000u);
  EXPECT_EQ(Uint64(stats["queries_served"]), kLocateCalls + kBatchPoints);
  EXPECT_EQ(Uint64(stats["total_cost"]), cost_sum_);
  EXPECT_DOUBLE_EQ(stats["mean_cost_lifetime"].number(),
                   double(cost_sum_) / (kLocateCalls + kBatchPoints));
  EXPECT_EQ(Uint64(stats["generation"]), 1u);
  const JsonValue& tuning = stats["tuning"];
  const double grid = tuning["grid_size"].number();
  EXPECT_GT(grid, 0);
  EXPECT_EQ(tuning["histogram"].array().size(), grid * grid);
  EXPECT_LE(tuning["start_points"].array().size(),
            Uint64(tuning["start_point_count"]));
  EXPECT_EQ(Uint64(tuning["hot_queries"]) + Uint64(tuning["fallback_queries"]),
            kLocateCalls + kBatchPoints);
  EXPECT_GT(Uint64(stats["memory"]["tuning_bytes"]), 0u);

  // The same message GetStats answers (its volatile fields aside).
  HttpReply reply;
  ASSERT_TRUE(HttpGet(server_->http_port(), "/api/stats", &reply).ok());
  v1::GetStatsResponse from_http;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(reply.body, &from_http).ok());
  v1::GetStatsResponse from_grpc = GetStats(*server_->NewStub());
  EXPECT_EQ(from_http.dataset().DebugString(),
            from_grpc.dataset().DebugString());
  EXPECT_EQ(from_http.walk_faces().DebugString(),
            from_grpc.walk_faces().DebugString());
  EXPECT_EQ(from_http.queries_served(), from_grpc.queries_served());
}

TEST_F(StatusHttpTest, HistoryHasOneValuePerSample) {
  const JsonValue history = GetJson(server_->http_port(), "/api/history");
  ASSERT_FALSE(history.is_null());
  EXPECT_EQ(history["t"].array().size(), history["qps"].array().size());
  EXPECT_EQ(history["t"].array().size(), history["mean_cost"].array().size());
}

TEST_F(StatusHttpTest, EdgesAreABoundedSampleInsideTheBox) {
  const JsonValue edges = GetJson(server_->http_port(), "/api/edges");
  ASSERT_FALSE(edges.is_null());
  const JsonArray& segments = edges["segments"].array();
  EXPECT_GT(segments.size(), 1000u);
  EXPECT_LE(segments.size(), 3000u);
  for (const JsonValue& segment : segments) {
    ASSERT_EQ(segment.array().size(), 4u);
    for (const JsonValue& coordinate : segment.array()) {
      EXPECT_GE(coordinate.number(), 0);
      EXPECT_LE(coordinate.number(), 1);
    }
  }
}

TEST_F(StatusHttpTest, UnknownPathsAre404AndOtherMethods405) {
  for (const std::string path : {"/nope", "/api/nope", "/metrics/x"}) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(server_->http_port(), path, &reply).ok());
    EXPECT_EQ(reply.status, 404u) << path;
  }
  for (const std::string method : {"POST", "PUT", "DELETE"}) {
    HttpReply reply;
    ASSERT_TRUE(
        SendHttp(server_->http_port(), method, "/metrics", &reply).ok());
    EXPECT_EQ(reply.status, 405u) << method;
    EXPECT_EQ(reply.headers["allow"], "GET, HEAD");
  }
}

TEST_F(StatusHttpTest, HeadHasTheHeadersOfGetAndNoBody) {
  HttpReply get, head;
  ASSERT_TRUE(HttpGet(server_->http_port(), "/", &get).ok());
  ASSERT_TRUE(SendHttp(server_->http_port(), "HEAD", "/", &head).ok());
  EXPECT_EQ(head.status, 200u);
  EXPECT_EQ(head.headers["content-type"], "text/html; charset=utf-8");
  EXPECT_EQ(head.headers["content-length"], std::to_string(get.body.size()));
  EXPECT_EQ(head.body, "");
  EXPECT_THAT(get.body, HasSubstr("<canvas id=\"map\""));
}

TEST_F(StatusHttpTest, AnHttpAddressInUseExitsOne) {
  std::unique_ptr<ServerProcess> second;
  ASSERT_TRUE(
      ServerProcess::Spawn(
          LOCATORD_PATH,
          {"--dataset", kDataset, "--listen", "127.0.0.1:0", "--http-listen",
           "127.0.0.1:" + std::to_string(server_->http_port())},
          &second)
          .ok());
  EXPECT_EQ(second->WaitForExit(std::chrono::seconds(30)), 1);
  EXPECT_THAT(second->StderrText(), HasSubstr("cannot listen on 127.0.0.1:"));
}

// Everything the HTTP side serves, for a locatord serving a dataset file,
// with a state dir and a mesh cache, and `flags`.
struct HttpOutputs {
  std::string dataset_path;
  std::string state_dir;
  std::string mesh_cache;
  std::string text;  // every body, one after another
  JsonValue stats;
};

void ReadHttpOutputs(const std::vector<std::string>& flags,
                     HttpOutputs* outputs) {
  const TestDatasetFile dataset;
  const test::ScratchDir state_dir;
  const test::ScratchDir mesh_cache;
  outputs->dataset_path = dataset.path();
  outputs->state_dir = state_dir.path();
  outputs->mesh_cache = mesh_cache.path();
  std::vector<std::string> all = {"--state-dir", state_dir.path(),
                                  "--mesh-cache", mesh_cache.path()};
  all.insert(all.end(), flags.begin(), flags.end());
  std::unique_ptr<LocatordWithHttp> server;
  const Status started = LocatordWithHttp::Start(dataset.path(), all, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  v1::LocateResponse located;
  ASSERT_TRUE(LocateOne(*server->NewStub(), {30.5, 20.25}, &located).ok());
  for (const std::string path :
       {"/api/stats", "/api/history", "/api/edges", "/metrics", "/"}) {
    HttpReply reply;
    ASSERT_TRUE(HttpGet(server->http_port(), path, &reply).ok());
    ASSERT_EQ(reply.status, 200u) << path;
    outputs->text += reply.body;
  }
  outputs->stats = GetJson(server->http_port(), "/api/stats");
}

TEST(StatusHttpRedactTest, WithRedactNoHttpOutputShowsAServerPath) {
  HttpOutputs outputs;
  ASSERT_NO_FATAL_FAILURE(ReadHttpOutputs({"--redact"}, &outputs));
  EXPECT_THAT(outputs.text, Not(HasSubstr(outputs.dataset_path)));
  EXPECT_THAT(outputs.text, Not(HasSubstr(outputs.state_dir)));
  EXPECT_THAT(outputs.text, Not(HasSubstr(outputs.mesh_cache)));
  EXPECT_EQ(outputs.stats["dataset"]["source"].string(), "");
  EXPECT_EQ(outputs.stats["tuning"]["persistence"]["state_path"].string(), "");
  EXPECT_EQ(outputs.stats["dataset"]["mesh_cache"]["path"].string(), "");
}

// The test above would pass vacuously if the paths never showed.
TEST(StatusHttpRedactTest, WithoutRedactStatsShowThePaths) {
  HttpOutputs outputs;
  ASSERT_NO_FATAL_FAILURE(ReadHttpOutputs({}, &outputs));
  EXPECT_THAT(outputs.text, HasSubstr(outputs.dataset_path));
  EXPECT_THAT(outputs.text, HasSubstr(outputs.state_dir));
  EXPECT_THAT(outputs.text, HasSubstr(outputs.mesh_cache));
  EXPECT_EQ(outputs.stats["dataset"]["source"].string(), outputs.dataset_path);
}

}  // namespace
}  // namespace locator::test
