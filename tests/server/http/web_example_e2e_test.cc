// The web example (client/web/, served at /web/) in a real browser:
// headless Chromium loads it from locatord beside a second dataset, the
// page draws the default dataset's edges and clicks the pixel of a known
// point (its ?click= parameter dispatches the click a user would make), and
// the DOM it leaves must show the triangle id, vertices and value gRPC
// answers for the point the page located, which lies within a pixel of the
// known one and so in the same triangle. The screenshot is kept as a test
// artifact (ARTIFACTS_DIR/web_example.png). The token typed into the page
// goes to its own origin without a question, and to another origin (a
// ?server= elsewhere) only once the user agrees to a confirm() naming it,
// asked once per origin (driven over the DevTools protocol, which answers
// the dialog). Skipped without Chromium.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "tests/core/scratch_dir.h"
#include "tests/server/http/browser.h"
#include "tests/server/http/devtools_page.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

// A 5 x 5 grid, 10 apart, every other column shifted up by 3 (so that no
// four points are cocircular and the triangulation is unique), with
// values TestValue(p).
void WriteGrid(const std::string& path) {
  std::ofstream out(path);
  out << "x,y,z\n";
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const Point2 p{10.0 * i, 10.0 * j + (i % 2) * 3};
      out << p.x << "," << p.y << "," << TestValue(p) << "\n";
    }
  }
}

double Number(const std::string& text) {
  return std::strtod(text.c_str(), nullptr);
}

TEST(WebExampleTest, AClickShowsTheTriangleAndValueGrpcAnswers) {
  if (!ChromiumInstalled()) {
    GTEST_SKIP() << kChromium << " is not installed (Debian package chromium)";
  }
  ScratchDir dir;
  const std::string grid = dir.path() + "/grid.csv";
  WriteGrid(grid);
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start("grid=" + grid,
                                      {"--dataset", "other=uniform:2000:1"},
                                      &server)
                  .ok());
  ASSERT_TRUE(server->WaitUntilServes("other").ok());
  auto stub = server->NewStub();

  // The centroid of the triangle (10, 13), (20, 20), (10, 23): several
  // pixels from each of its edges at the page's scale (~13 px per unit).
  const Point2 known{40.0 / 3, 56.0 / 3};
  v1::LocateResponse at_known;
  ASSERT_TRUE(LocateOne(*stub, known, &at_known, "grid").ok());
  ASSERT_EQ(at_known.type(), v1::LOCATION_TYPE_FACE);

  const std::string url =
      "http://127.0.0.1:" + std::to_string(server->http_port()) +
      "/web/?click=" + std::to_string(known.x) + "," + std::to_string(known.y);
  const std::string dom = RunChromium(url, {"--dump-dom"});
  const std::string result = StartTag(dom, "result");
  ASSERT_EQ(Attribute(result, "data-state"), "done") << dom;

  // The point the page located: the click's pixel, back in dataset
  // coordinates.
  const Point2 clicked{Number(Attribute(result, "data-x")),
                       Number(Attribute(result, "data-y"))};
  EXPECT_LT(std::hypot(clicked.x - known.x, clicked.y - known.y), 0.5);
  v1::LocateResponse expected;
  ASSERT_TRUE(LocateOne(*stub, clicked, &expected, "grid").ok());
  EXPECT_EQ(expected.triangle_id(), at_known.triangle_id());

  const auto field = [&](const std::string& id) {
    return Attribute(StartTag(dom, id), "data-value");
  };
  EXPECT_EQ(field("result-type"), "LOCATION_TYPE_FACE");
  EXPECT_EQ(field("result-triangle"), std::to_string(expected.triangle_id()));
  EXPECT_EQ(field("result-vertices"),
            std::to_string(expected.vertex_ids(0)) + "," +
                std::to_string(expected.vertex_ids(1)) + "," +
                std::to_string(expected.vertex_ids(2)));
  ASSERT_TRUE(expected.has_value());
  EXPECT_EQ(Number(field("result-value")), expected.value());
  EXPECT_NEAR(expected.value(), TestValue(clicked), 1e-9);

  ExpectScreenshotDrawn(url, std::string(ARTIFACTS_DIR) + "/web_example.png",
                        1280, 700, 20000);
}

constexpr char kToken[] = "web-token-5678";

// What the web example's page shows once it has settled: the result's
// state when a click was answered, else the error shown.
constexpr char kOutcome[] =
    "(() => { const state = document.getElementById('result').dataset.state;"
    "  const error = document.getElementById('error').textContent;"
    "  return state === 'done' ? 'done' : (error ? 'error: ' + error : ''); "
    "})()";

class WebExampleTokenTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!ChromiumInstalled()) {
      GTEST_SKIP() << kChromium
                   << " is not installed (Debian package chromium)";
    }
    const std::string token_file = dir_.path() + "/token";
    std::ofstream(token_file) << kToken << "\n";
    // The page's origin: a locatord without tokens, serving /web/.
    ASSERT_TRUE(LocatordWithHttp::Start("uniform:500:2", {}, &page_).ok());
    // The server the page is pointed at: tokens on, CORS for that origin.
    ASSERT_TRUE(LocatordWithHttp::Start("grid=uniform:2000:1",
                                        {"--token-file", token_file,
                                         "--http-cors-origin", PageOrigin()},
                                        &api_, kToken)
                    .ok());
  }

  std::string PageOrigin() const {
    return "http://127.0.0.1:" + std::to_string(page_->http_port());
  }
  std::string ApiOrigin() const {
    return "http://127.0.0.1:" + std::to_string(api_->http_port());
  }
  // The web example from `origin` pointed at the token server, with the
  // token in the link, clicking the middle of the map.
  std::string PageUrl(const std::string& origin) const {
    return origin + "/web/?server=" + ApiOrigin() +
           "&click=0.5,0.5#token=" + kToken;
  }

  ScratchDir dir_;
  std::unique_ptr<LocatordWithHttp> page_;
  std::unique_ptr<LocatordWithHttp> api_;
};

TEST_F(WebExampleTokenTest, ItsOwnOriginGetsTheTokenWithoutAQuestion) {
  std::unique_ptr<DevToolsPage> page;
  ASSERT_TRUE(DevToolsPage::Open(PageUrl(ApiOrigin()), false, &page).ok());
  std::string outcome;
  ASSERT_TRUE(page->WaitForValue(kOutcome, &outcome).ok());
  EXPECT_EQ(outcome, "done");
  EXPECT_TRUE(page->dialogs().empty());
}

TEST_F(WebExampleTokenTest, AnotherOriginGetsItOnlyWhenTheUserAgrees) {
  // Declined: the calls go without the token, and the server wants one.
  std::unique_ptr<DevToolsPage> declined;
  ASSERT_TRUE(DevToolsPage::Open(PageUrl(PageOrigin()), false, &declined).ok());
  std::string outcome;
  ASSERT_TRUE(declined->WaitForValue(kOutcome, &outcome).ok());
  EXPECT_THAT(outcome, ::testing::HasSubstr("Bearer <token>"));
  ASSERT_EQ(declined->dialogs().size(), 1u);
  EXPECT_THAT(declined->dialogs()[0], ::testing::HasSubstr(ApiOrigin()));

  // Agreed: the list, the edges and the click's :locate all carry it, and
  // the question was asked once.
  std::unique_ptr<DevToolsPage> agreed;
  ASSERT_TRUE(DevToolsPage::Open(PageUrl(PageOrigin()), true, &agreed).ok());
  ASSERT_TRUE(agreed->WaitForValue(kOutcome, &outcome).ok());
  EXPECT_EQ(outcome, "done");
  ASSERT_EQ(agreed->dialogs().size(), 1u);
  EXPECT_THAT(agreed->dialogs()[0], ::testing::HasSubstr(ApiOrigin()));
}

}  // namespace
}  // namespace locator::test
