// The status page in a real browser: locatord serves clustered traffic,
// headless Chromium loads "/" and runs its script, and the DOM it leaves
// must show the heat map's hottest cells inside the cluster and the same
// figures /api/stats reports; on a constrained dataset it must have drawn
// the domain's boundary and holes and the breaklines /api/edges serves,
// with their legend. With tokens on, the page asks for the data token and,
// given one (#token=), shows the statistics. The screenshots are kept as
// test artifacts
// (ARTIFACTS_DIR/status_page.png, status_page_domain.png). Skipped when
// Chromium is not installed.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/http/browser.h"
#include "tests/server/http/json_value.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

constexpr int kClusteredQueries = 3000;
constexpr int kQueriesPerBurst = 1000;

// When the latest history sample /api/history reports was taken (0: none
// yet).
double LatestSampleTime(int port) {
  const JsonValue history = GetJson(port, "/api/history");
  const JsonArray& taken = history["t"].array();
  return taken.empty() ? 0 : taken.back().number();
}

// The data-value of the figure with id `id`.
std::string Figure(const std::string& dom, const std::string& id) {
  return Attribute(StartTag(dom, id), "data-value");
}

// Takes a 1280x900 screenshot of `url` into ARTIFACTS_DIR/`name` and
// checks that something is drawn in it.
void ExpectPageDrawn(const std::string& url, const std::string& name) {
  ExpectScreenshotDrawn(url, std::string(ARTIFACTS_DIR) + "/" + name, 1280, 900,
                        30000);
}

TEST(StatusPageTest, HeatMapAndFiguresShowTheClusteredTraffic) {
  if (access(kChromium, X_OK) != 0) {
    GTEST_SKIP() << kChromium << " is not installed (Debian package chromium)";
  }
  std::unique_ptr<LocatordWithHttp> server;
  const Status started =
      LocatordWithHttp::Start("uniform:20000:1", {}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  const int port = server->http_port();

  // All traffic in one rectangle near the lower-left corner.
  const JsonValue before = GetJson(port, "/api/stats");
  const JsonValue& box = before["dataset"]["bounding_box"];
  const double min_x = box["min_x"].number(), min_y = box["min_y"].number();
  const double w = box["max_x"].number() - min_x;
  const double h = box["max_y"].number() - min_y;
  const BoundingBox cluster{min_x + 0.05 * w, min_y + 0.05 * h, min_x + 0.2 * w,
                            min_y + 0.2 * h};
  auto stub = server->NewStub();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(cluster.min_x, cluster.max_x);
  std::uniform_real_distribution<double> y(cluster.min_y, cluster.max_y);
  for (int i = 0; i < kClusteredQueries; ++i) {
    v1::LocateResponse response;
    ASSERT_TRUE(test::LocateOne(*stub, {x(rng), y(rng)}, &response).ok());
    // Spread over a few history samples, so the charts have a curve: the
    // next burst starts once a sample taken after this one has landed.
    if ((i + 1) % kQueriesPerBurst == 0) {
      const double burst_end = LatestSampleTime(port);
      EXPECT_TRUE(
          test::WaitUntil([&] { return LatestSampleTime(port) > burst_end; }));
    }
  }
  // Fold every query into the histogram the page draws.
  grpc::ClientContext context;
  v1::RetuneResponse retuned;
  ASSERT_TRUE(stub->Retune(&context, {}, &retuned).ok());

  const JsonValue stats = GetJson(port, "/api/stats");
  // Proto JSON: 64-bit integers are strings.
  ASSERT_EQ(stats["queries_served"].string(),
            std::to_string(kClusteredQueries));
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/";
  const std::string dom = RunChromium(url, {"--dump-dom"});

  const size_t body_at = dom.find("<body");
  ASSERT_NE(body_at, std::string::npos) << dom;
  const std::string body_tag =
      dom.substr(body_at, dom.find('>', body_at) - body_at + 1);
  EXPECT_EQ(Attribute(body_tag, "data-rendered-version"),
            stats["tuning"]["snapshot_version"].string());
  EXPECT_NE(Attribute(body_tag, "data-render-count"), "0");

  EXPECT_EQ(Figure(dom, "queries"), std::to_string(kClusteredQueries));
  EXPECT_NE(dom.find(">3,000</span>"), std::string::npos);
  EXPECT_EQ(Figure(dom, "snapshot-version"),
            stats["tuning"]["snapshot_version"].string());
  EXPECT_EQ(Figure(dom, "retunes"), stats["tuning"]["retune_count"].string());
  EXPECT_EQ(std::strtod(Figure(dom, "mean-cost-lifetime").c_str(), nullptr),
            stats["mean_cost_lifetime"].number());
  EXPECT_EQ(Figure(dom, "hot-queries"),
            stats["tuning"]["hot_queries"].string());
  EXPECT_EQ(Figure(dom, "triangulation-bytes"),
            stats["memory"]["triangulation_bytes"].string());

  // The hottest cells the page drew lie in the cluster, the first one
  // holding the histogram's largest count.
  JsonValue cells;
  const std::string cells_text =
      Attribute(StartTag(dom, "hot-cells"), "data-cells");
  ASSERT_TRUE(ParseJson(cells_text, &cells).ok()) << cells_text;
  ASSERT_FALSE(cells.array().empty());
  const JsonValue& tuning = stats["tuning"];
  const double n = tuning["grid_size"].number();
  const JsonValue& grid = tuning["grid_box"];
  const double cell_w = (grid["max_x"].number() - grid["min_x"].number()) / n;
  const double cell_h = (grid["max_y"].number() - grid["min_y"].number()) / n;
  double max_count = 0;
  for (const JsonValue& count : tuning["histogram"].array()) {
    max_count = std::max(max_count, count.number());
  }
  EXPECT_EQ(cells.array()[0]["count"].number(), max_count);
  for (const JsonValue& cell : cells.array()) {
    const double x0 = grid["min_x"].number() + cell["i"].number() * cell_w;
    const double y0 = grid["min_y"].number() + cell["j"].number() * cell_h;
    EXPECT_TRUE(x0 < cluster.max_x && x0 + cell_w > cluster.min_x &&
                y0 < cluster.max_y && y0 + cell_h > cluster.min_y)
        << "cell " << cell["i"].number() << "," << cell["j"].number();
  }

  ExpectPageDrawn(url, "status_page.png");
}

// A .poly terrain: the square [0, 8]^2 with a bay cut in from the top to
// (4, 5), a square lake (2, 1)-(3, 2) marked by a hole point, and a
// breakline (1, 3)-(7, 3) through the grid points between its ends.
std::string TerrainPoly() {
  std::ostringstream poly;
  poly << "81 2 0 0\n";
  for (int i = 0; i < 81; ++i)
    poly << i << " " << i % 9 << " " << i / 9 << "\n";
  const auto index = [](int x, int y) { return y * 9 + x; };
  const std::vector<std::array<int, 2>> segments = {
      {index(0, 0), index(8, 0)}, {index(8, 0), index(8, 8)},
      {index(8, 8), index(4, 5)}, {index(4, 5), index(0, 8)},
      {index(0, 8), index(0, 0)}, {index(2, 1), index(3, 1)},
      {index(3, 1), index(3, 2)}, {index(3, 2), index(2, 2)},
      {index(2, 2), index(2, 1)}, {index(1, 3), index(7, 3)}};
  poly << segments.size() << " 0\n";
  for (size_t k = 0; k < segments.size(); ++k) {
    poly << k << " " << segments[k][0] << " " << segments[k][1] << "\n";
  }
  poly << "1\n0 2.5 1.5\n";
  return poly.str();
}

TEST(StatusPageTest, DomainBoundaryHolesAndBreaklinesAreDrawn) {
  if (access(kChromium, X_OK) != 0) {
    GTEST_SKIP() << kChromium << " is not installed (Debian package chromium)";
  }
  ScratchDir dir;
  const std::string poly_path = dir.path() + "/terrain.poly";
  std::ofstream(poly_path) << TerrainPoly();
  std::unique_ptr<LocatordWithHttp> server;
  const Status started = LocatordWithHttp::Start(poly_path, {}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  const int port = server->http_port();

  const JsonValue edges = GetJson(port, "/api/edges");
  const size_t boundary = edges["boundary"].array().size();
  const size_t breaklines = edges["breaklines"].array().size();
  // The outer boundary (three sides of 8 unit edges, and the bay's two
  // sides, which pass through no grid point) and the lake's 4 unit edges;
  // the breakline's 6 unit edges.
  EXPECT_EQ(boundary, 3 * 8u + 2u + 4u);
  EXPECT_EQ(breaklines, 6u);

  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/";
  const std::string dom = RunChromium(url, {"--dump-dom"});
  const std::string layers = StartTag(dom, "domain-layers");
  EXPECT_EQ(Attribute(layers, "data-boundary"), std::to_string(boundary))
      << dom;
  EXPECT_EQ(Attribute(layers, "data-breaklines"), std::to_string(breaklines));
  // The legend names both layers once there are any.
  const std::string legend = StartTag(dom, "domain-legend");
  ASSERT_NE(legend, "") << dom;
  EXPECT_EQ(legend.find(" hidden"), std::string::npos) << legend;
  ExpectPageDrawn(url, "status_page_domain.png");
}

TEST(StatusPageTest, WithTokensThePageAsksForTheDataToken) {
  if (access(kChromium, X_OK) != 0) {
    GTEST_SKIP() << kChromium << " is not installed (Debian package chromium)";
  }
  ScratchDir dir;
  const std::string token_file = dir.path() + "/token";
  std::ofstream(token_file) << "status-token-42\n";
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start("uniform:2000:1",
                                      {"--token-file", token_file}, &server,
                                      "status-token-42")
                  .ok());
  const std::string url =
      "http://127.0.0.1:" + std::to_string(server->http_port()) + "/";

  const std::string asked = RunChromium(url, {"--dump-dom"});
  EXPECT_EQ(Attribute(StartTag(asked, "state"), "class"), "state locked");
  EXPECT_NE(StartTag(asked, "token"), "");
  EXPECT_EQ(StartTag(asked, "token").find(" hidden"), std::string::npos)
      << StartTag(asked, "token");
  EXPECT_EQ(Attribute(StartTag(asked, "queries"), "data-value"), "");

  const std::string shown =
      RunChromium(url + "#token=status-token-42", {"--dump-dom"});
  EXPECT_EQ(Attribute(StartTag(shown, "state"), "class"), "state serving");
  EXPECT_EQ(Figure(shown, "start-points").empty(), false);
}

}  // namespace
}  // namespace locator::test
