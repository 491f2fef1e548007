// The status page in a real browser: locatord serves clustered traffic,
// headless Chromium loads "/" and runs its script, and the DOM it leaves
// must show the heat map's hottest cells inside the cluster and the same
// figures /api/stats reports; on a constrained dataset it must have drawn
// the domain's boundary and holes and the breaklines /api/edges serves,
// with their legend. The screenshots are kept as test artifacts
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
#include "tests/server/e2e_support.h"
#include "tests/server/http/json_value.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

constexpr char kChromium[] = "/usr/bin/chromium";
constexpr int kClusteredQueries = 3000;
constexpr int kQueriesPerBurst = 1000;

// When the latest history sample /api/history reports was taken (0: none
// yet).
double LatestSampleTime(int port) {
  const JsonValue history = GetJson(port, "/api/history");
  const JsonArray& taken = history["t"].array();
  return taken.empty() ? 0 : taken.back().number();
}

// Runs headless Chromium on `url` with `flags`; returns its stdout. Its
// stderr goes to a file next to the fresh profile directory.
std::string RunChromium(const std::string& url,
                        const std::vector<std::string>& flags) {
  std::string dir_template = ::testing::TempDir() + "chromium-XXXXXX";
  EXPECT_NE(mkdtemp(dir_template.data()), nullptr);
  std::string command = std::string("timeout 120 ") + kChromium +
                        " --headless --no-sandbox --disable-gpu"
                        " --disable-quic --no-first-run"
                        " --disable-background-networking"
                        " --disable-component-update --disable-sync"
                        " --virtual-time-budget=6000"
                        " --user-data-dir=" +
                        dir_template + "/profile";
  for (const std::string& flag : flags) command += " " + flag;
  command += " " + url + " 2>" + dir_template + "/stderr.txt";
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr) << command;
  if (pipe == nullptr) return out;
  char chunk[4096];
  size_t got;
  while ((got = fread(chunk, 1, sizeof(chunk), pipe)) > 0)
    out.append(chunk, got);
  const int exit_status = pclose(pipe);
  std::ifstream stderr_file(dir_template + "/stderr.txt");
  const std::string stderr_text((std::istreambuf_iterator<char>(stderr_file)),
                                std::istreambuf_iterator<char>());
  EXPECT_EQ(exit_status, 0) << command << "\n" << stderr_text;
  std::filesystem::remove_all(dir_template);
  return out;
}

std::string HtmlUnescape(std::string text) {
  const std::pair<std::string, std::string> entities[] = {{"&quot;", "\""},
                                                          {"&#39;", "'"},
                                                          {"&lt;", "<"},
                                                          {"&gt;", ">"},
                                                          {"&amp;", "&"}};
  for (const auto& [entity, plain] : entities) {
    for (size_t at = text.find(entity); at != std::string::npos;
         at = text.find(entity, at + plain.size())) {
      text.replace(at, entity.size(), plain);
    }
  }
  return text;
}

// The start tag of the element with id `id` in `dom` ("" if none).
std::string StartTag(const std::string& dom, const std::string& id) {
  const size_t at = dom.find(" id=\"" + id + "\"");
  if (at == std::string::npos) return "";
  const size_t begin = dom.rfind('<', at);
  return dom.substr(begin, dom.find('>', at) - begin + 1);
}

// Attribute `name` of a start tag, unescaped ("" if absent).
std::string Attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size();
  return HtmlUnescape(tag.substr(begin, tag.find('"', begin) - begin));
}

// The data-value of the figure with id `id`.
std::string Figure(const std::string& dom, const std::string& id) {
  return Attribute(StartTag(dom, id), "data-value");
}

// Width and height from a PNG's IHDR chunk; {0, 0} if it is not a PNG.
std::pair<uint32_t, uint32_t> PngSize(const std::string& png) {
  if (png.size() < 24 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      png.compare(12, 4, "IHDR") != 0) {
    return {0, 0};
  }
  const auto be32 = [&png](size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) {
      v = (v << 8) | static_cast<unsigned char>(png[at + i]);
    }
    return v;
  };
  return {be32(16), be32(20)};
}

// Takes a 1280x900 screenshot of `url` into ARTIFACTS_DIR/`name` and
// checks that it is a PNG of that size with something drawn in it.
void ExpectScreenshotDrawn(const std::string& url, const std::string& name) {
  const std::string artifacts = ARTIFACTS_DIR;
  std::filesystem::create_directories(artifacts);
  const std::string png_path = artifacts + "/" + name;
  std::filesystem::remove(png_path);
  RunChromium(url, {"--screenshot=" + png_path, "--window-size=1280,900"});
  std::ifstream file(png_path, std::ios::binary);
  ASSERT_TRUE(file.good()) << png_path;
  const std::string png((std::istreambuf_iterator<char>(file)),
                        std::istreambuf_iterator<char>());
  EXPECT_EQ(PngSize(png), std::make_pair(1280u, 900u));
  // A blank 1280x900 page compresses to a few KB; the drawn one does not.
  EXPECT_GT(png.size(), 30000u);
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

  ExpectScreenshotDrawn(url, "status_page.png");
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
  ExpectScreenshotDrawn(url, "status_page_domain.png");
}

}  // namespace
}  // namespace locator::test
