#include "server/http/status/status_endpoints.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/app/proto_convert.h"
#include "server/metrics/engine_collector.h"
#include "server/metrics/metrics_text.h"
#include "server/serving/access_policy.h"
#include "tests/server/http/json_value.h"
#include "tests/server/http/prometheus_text.h"

namespace locator {
namespace {

using test::JsonArray;
using test::JsonValue;
using test::ParseJson;
using test::ParsePrometheusText;
using test::PrometheusText;
using ::testing::HasSubstr;

class StatusEndpointsTest : public ::testing::Test {
 protected:
  // Endpoints over engine_, one dataset named "default", wired as locatord
  // wires them (there through LocatorApp::CurrentStats).
  StatusEndpoints Endpoints() {
    const auto known = [](std::string_view dataset) {
      return dataset.empty() || dataset == "default"
                 ? Status::OK()
                 : Status::NotFound("unknown dataset '" + std::string(dataset) +
                                    "'");
    };
    const StatsSource stats = [this, known](std::string_view dataset,
                                            v1::GetStatsResponse* out) {
      if (Status status = known(dataset); !status.ok()) return status;
      if (engine_ == nullptr) return Status::Unavailable("loading");
      ToGetStatsResponse(engine_->Stats(), out);
      return Status::OK();
    };
    auto collector = std::make_shared<EngineCollector>([stats] {
      DatasetStatsSample sample;
      sample.dataset = "default";
      v1::GetStatsResponse response;
      if (stats("", &response).ok()) sample.stats = response;
      return std::vector<DatasetStatsSample>{sample};
    });
    return StatusEndpoints(
        {.authorize = authorize_,
         .stats = stats,
         .edges =
             [this, known](std::string_view dataset, MapEdges* edges) {
               if (Status status = known(dataset); !status.ok()) return status;
               if (engine_ == nullptr) return Status::Unavailable("loading");
               edges->segments = engine_->EdgeSample();
               edges->boundary = engine_->domain_outline().boundary;
               edges->breaklines = engine_->domain_outline().breaklines;
               return Status::OK();
             },
         .history =
             [this, known](std::string_view dataset,
                           const StatsHistory** history) {
               *history = &history_;
               return known(dataset);
             },
         .metrics_text = [collector] { return MetricsText({collector}); }});
  }

  void Load(Dataset dataset = GenerateUniform(2000, 3)) {
    StatusOr<std::unique_ptr<Engine>> engine =
        Engine::Create(std::move(dataset), EngineOptions());
    ASSERT_TRUE(engine.ok());
    engine_ = *std::move(engine);
  }

  std::shared_ptr<Engine> engine_;
  StatsHistory history_;
  StatusAuthorizer authorize_;  // null: the status API is public
};

TEST_F(StatusEndpointsTest, StatsAndEdgesAreAdmittedByTheAuthorizer) {
  const AccessPolicy policy("data-token", "");
  authorize_ = [&policy](std::optional<std::string_view> authorization) {
    return policy.CheckAuthorization(authorization, AccessPolicy::Scope::kData);
  };
  const StatusEndpoints endpoints = Endpoints();
  Load();
  for (const char* path : {"/api/stats", "/api/edges"}) {
    EXPECT_EQ(endpoints.Handle(path).status, 401u) << path;
    EXPECT_EQ(endpoints.Handle(path, "", "Bearer guess").status, 403u) << path;
    const HttpResponse admitted =
        endpoints.Handle(path, "", "Bearer data-token");
    EXPECT_EQ(admitted.status, 200u) << path;
  }
  // Counts and costs only, like /metrics: no token.
  EXPECT_EQ(endpoints.Handle("/api/history").status, 200u);
  EXPECT_EQ(endpoints.Handle("/metrics").status, 200u);
  EXPECT_EQ(endpoints.Handle("/").status, 200u);
}

TEST_F(StatusEndpointsTest, WhileLoadingTheApiIs503AndMetricsSayNotLoaded) {
  const StatusEndpoints endpoints = Endpoints();
  for (const char* path : {"/api/stats", "/api/edges"}) {
    const HttpResponse reply = endpoints.Handle(path);
    EXPECT_EQ(reply.status, 503u) << path;
    EXPECT_EQ(reply.content_type, "application/json");
    EXPECT_EQ(reply.body, R"({"state":"loading"})");
  }
  const HttpResponse history = endpoints.Handle("/api/history");
  EXPECT_EQ(history.status, 200u);
  EXPECT_EQ(history.body, R"({"t":[],"qps":[],"mean_cost":[]})");
  const HttpResponse metrics = endpoints.Handle("/metrics");
  EXPECT_EQ(metrics.status, 200u);
  PrometheusText text;
  ASSERT_TRUE(ParsePrometheusText(metrics.body, &text).ok()) << metrics.body;
  EXPECT_EQ(text.Value("locator_engine_loaded", {{"dataset", "default"}}), 0);
  EXPECT_EQ(text.Value("locator_queries_total"), std::nullopt);
  EXPECT_EQ(endpoints.Handle("/").status, 200u);
}

TEST_F(StatusEndpointsTest, FollowsTheCurrentEngine) {
  const StatusEndpoints endpoints = Endpoints();
  Load();
  LocateResult result;
  for (int i = 0; i < 10; ++i) {
    ASSERT_TRUE(engine_->Locate({0.1 * i, 0.5}, &result).ok());
  }
  history_.Record(1, 0, 0, std::chrono::system_clock::now());
  history_.Record(1, 10, 40,
                  std::chrono::system_clock::now() + std::chrono::seconds(1));
  JsonValue stats;
  ASSERT_TRUE(ParseJson(endpoints.Handle("/api/stats").body, &stats).ok());
  // Proto JSON: 64-bit integers are strings.
  EXPECT_EQ(stats["queries_served"].string(), "10");
  EXPECT_EQ(stats["dataset"]["source"].string(), "uniform:2000:3");
  JsonValue history;
  ASSERT_TRUE(ParseJson(endpoints.Handle("/api/history").body, &history).ok());
  EXPECT_EQ(history["mean_cost"].array().at(0).number(), 4);

  PrometheusText text;
  ASSERT_TRUE(
      ParsePrometheusText(endpoints.Handle("/metrics").body, &text).ok());
  EXPECT_EQ(text.Value("locator_queries_total", {{"dataset", "default"}}), 10);

  // A new engine: the same endpoints now describe it.
  Load();
  ASSERT_TRUE(ParseJson(endpoints.Handle("/api/stats").body, &stats).ok());
  EXPECT_EQ(stats["queries_served"].string(), "0");
  JsonValue edges;
  ASSERT_TRUE(ParseJson(endpoints.Handle("/api/edges").body, &edges).ok());
  EXPECT_EQ(edges["segments"].array().size(), engine_->EdgeSample().size());
  // A plain point cloud has no domain outline.
  EXPECT_TRUE(edges["boundary"].array().empty());
  EXPECT_TRUE(edges["breaklines"].array().empty());
}

TEST_F(StatusEndpointsTest, EdgesCarryTheDomainBoundaryAndBreaklines) {
  const StatusEndpoints endpoints = Endpoints();
  Dataset dataset = GenerateUniform(2000, 3);
  dataset.constraints.rings = {
      Polyline{{{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}, {}},
      Polyline{{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}, {}}};
  dataset.constraints.breaklines = {Polyline{{{0.2, 0.2}, {0.3, 0.8}}, {}}};
  Load(std::move(dataset));
  const DomainOutline& outline = engine_->domain_outline();
  ASSERT_FALSE(outline.boundary.empty());
  ASSERT_FALSE(outline.breaklines.empty());
  JsonValue edges;
  ASSERT_TRUE(ParseJson(endpoints.Handle("/api/edges").body, &edges).ok());
  const JsonArray& boundary = edges["boundary"].array();
  const JsonArray& breaklines = edges["breaklines"].array();
  ASSERT_EQ(boundary.size(), outline.boundary.size());
  ASSERT_EQ(breaklines.size(), outline.breaklines.size());
  const auto& [a, b] = outline.breaklines.front();
  ASSERT_EQ(breaklines.front().array().size(), 4u);
  EXPECT_EQ(breaklines.front().array()[0].number(), a.x);
  EXPECT_EQ(breaklines.front().array()[1].number(), a.y);
  EXPECT_EQ(breaklines.front().array()[2].number(), b.x);
  EXPECT_EQ(breaklines.front().array()[3].number(), b.y);
}

TEST_F(StatusEndpointsTest, TheApiPathsTakeADatasetAndRefuseUnknownOnes) {
  const StatusEndpoints endpoints = Endpoints();
  Load();
  for (const char* path : {"/api/stats", "/api/edges", "/api/history"}) {
    EXPECT_EQ(endpoints.Handle(path, "dataset=default").status, 200u) << path;
    EXPECT_EQ(endpoints.Handle(path, "x=1&dataset=default&y=2").body,
              endpoints.Handle(path).body)
        << path;
    const HttpResponse unknown = endpoints.Handle(path, "dataset=nope");
    EXPECT_EQ(unknown.status, 404u) << path;
    EXPECT_EQ(unknown.content_type, "application/json");
    JsonValue error;
    ASSERT_TRUE(ParseJson(unknown.body, &error).ok()) << unknown.body;
    EXPECT_EQ(error["code"].number(), 5);  // NOT_FOUND
    EXPECT_EQ(error["status"].string(), "NOT_FOUND");
    EXPECT_EQ(error["message"].string(), "unknown dataset 'nope'");
  }
}

TEST_F(StatusEndpointsTest, ServesTheWebExampleUnderWeb) {
  const StatusEndpoints endpoints = Endpoints();
  const HttpResponse index = endpoints.Handle("/web/");
  EXPECT_EQ(index.status, 200u);
  EXPECT_EQ(index.content_type, "text/html; charset=utf-8");
  EXPECT_EQ(endpoints.Handle("/web/index.html").body, index.body);
  EXPECT_THAT(endpoints.Handle("/web/app.js").body, HasSubstr(":locate"));
  EXPECT_EQ(endpoints.Handle("/web/style.css").status, 200u);
  const HttpResponse bare = endpoints.Handle("/web");
  EXPECT_EQ(bare.status, 301u);
  ASSERT_EQ(bare.headers.size(), 1u);
  EXPECT_EQ(bare.headers[0].second, "/web/");
  for (const char* path : {"/web/nope", "/web/../index.html", "/web//app.js"}) {
    EXPECT_EQ(endpoints.Handle(path).status, 404u) << path;
  }
}

TEST_F(StatusEndpointsTest, ServesTheEmbeddedPage) {
  const StatusEndpoints endpoints = Endpoints();
  const HttpResponse index = endpoints.Handle("/");
  EXPECT_EQ(index.content_type, "text/html; charset=utf-8");
  EXPECT_THAT(index.body, HasSubstr("<script src=\"app.js\">"));
  EXPECT_EQ(endpoints.Handle("/index.html").body, index.body);
  const HttpResponse script = endpoints.Handle("/app.js");
  EXPECT_EQ(script.status, 200u);
  EXPECT_EQ(script.content_type, "text/javascript; charset=utf-8");
  EXPECT_THAT(script.body, HasSubstr("/api/stats"));
  EXPECT_EQ(endpoints.Handle("/style.css").content_type,
            "text/css; charset=utf-8");
  for (const char* path : {"/nope", "/api/", "/app.js/", "//app.js", ""}) {
    EXPECT_EQ(endpoints.Handle(path).status, 404u) << path;
  }
}

}  // namespace
}  // namespace locator
