// The web map (client/web/, MapLibre GL JS embedded in locatord's /web/)
// over a dataset with a CRS, in headless Chromium with its software WebGL
// (SwiftShader), driven over the DevTools protocol in real time (MapLibre
// parses GeoJSON in web workers, which --dump-dom's virtual time stalls).
// The page shows a hill in UTM zone 33N (a GeoPackage made by ogr2ogr) as
// its hillshade tiles over 3D terrain from its terrain tiles, clicks a
// lon/lat point and draws a line (its ?click= and ?profile= parameters
// dispatch the clicks a user would make). Once the map has loaded its tiles
// and the triangle found is in the map's data, the values shown must be
// gRPC's for the point the page located (Locate with crs EPSG:4326) and the
// profile gRPC's Profile of the same line; the window's screenshot must be
// a drawn map, not a blank canvas (the relief's greys over much of the
// map), and is kept
// as a test artifact (ARTIFACTS_DIR/web_map.png). Skipped without Chromium.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/browser.h"
#include "tests/server/http/devtools_page.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/tiles/png_decode.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

// The hill's centre (UTM 33N 500000, 5500000) is 15°E 49.6525°N.
constexpr char kClick[] = "15.004,49.657";
constexpr char kLine[] = "14.97,49.64;15.03,49.67";

// Once the page has answered the click and the line, and the map has drawn
// its tiles and holds the triangle found, its figures as "NAME=VALUE" lines;
// "" until then (an error shown ends the wait with it).
constexpr char kSettled[] = R"JS((() => {
  const error = document.getElementById('error').textContent;
  if (error) return 'error=' + error;
  const result = document.getElementById('result');
  const profile = document.getElementById('profile');
  if (result.dataset.state !== 'done' || profile.dataset.state !== 'done') {
    return '';
  }
  if (!map.loaded() || !map.areTilesLoaded() || !map.getLayer('relief') ||
      map.querySourceFeatures('hit').length === 0) {
    return '';
  }
  const field = (id) => document.getElementById(id).dataset.value;
  return ['x=' + result.dataset.x, 'y=' + result.dataset.y,
          'triangle=' + field('result-triangle'),
          'vertices=' + field('result-vertices'),
          'value=' + field('result-value'),
          'from=' + profile.dataset.from, 'to=' + profile.dataset.to,
          'length=' + field('profile-length'),
          'crossings=' + field('profile-crossings'),
          'breakpoints=' + field('profile-points'),
          'chart=' + document.querySelectorAll('#profile-chart path').length,
          'terrain=' + (map.getTerrain() ? map.getTerrain().source : '')]
      .join('\n');
})())JS";

// The NAME=VALUE lines of `text` as a map.
std::map<std::string, std::string> Fields(const std::string& text) {
  std::map<std::string, std::string> fields;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const size_t equals = line.find('=');
    fields[line.substr(0, equals)] = line.substr(equals + 1);
  }
  return fields;
}

Point2 PointOf(const std::string& text) {
  const size_t comma = text.find(',');
  return Point2{std::strtod(text.substr(0, comma).c_str(), nullptr),
                std::strtod(text.substr(comma + 1).c_str(), nullptr)};
}

TEST(WebMapTest, AClickAndALineShowWhatGrpcAnswersOnTheTerrain) {
  if (!ChromiumInstalled()) {
    GTEST_SKIP() << kChromium << " is not installed (Debian package chromium)";
  }
  ScratchDir dir;
  const std::string gpkg = gis::testing::UtmHillGeoPackage(30, dir.path());
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start("terrain=" + gpkg, {}, &server).ok());
  auto stub = server->NewStub();

  std::unique_ptr<DevToolsPage> page;
  ASSERT_TRUE(DevToolsPage::Open(
                  "http://127.0.0.1:" + std::to_string(server->http_port()) +
                      "/web/?click=" + kClick + "&profile=" + kLine,
                  /*accept_dialogs=*/false, &page)
                  .ok());
  std::string settled;
  ASSERT_TRUE(page->WaitForValue(kSettled, &settled).ok());
  const std::map<std::string, std::string> shown = Fields(settled);
  ASSERT_FALSE(shown.contains("error")) << shown.at("error");
  EXPECT_EQ(shown.at("terrain"), "terrain");
  EXPECT_EQ(shown.at("chart"), "1");

  // The point the page located, a pixel from the one asked for, in lon/lat.
  const Point2 clicked = PointOf(shown.at("x") + "," + shown.at("y"));
  const Point2 asked = PointOf(kClick);
  EXPECT_NEAR(clicked.x, asked.x, 1e-3);
  EXPECT_NEAR(clicked.y, asked.y, 1e-3);
  grpc::ClientContext locate_context;
  v1::LocateRequest locate = LocateRequestFor(clicked, "terrain");
  locate.set_crs("EPSG:4326");
  v1::LocateResponse expected;
  ASSERT_TRUE(stub->Locate(&locate_context, locate, &expected).ok());
  ASSERT_EQ(expected.type(), v1::LOCATION_TYPE_FACE);
  EXPECT_EQ(shown.at("triangle"), std::to_string(expected.triangle_id()));
  EXPECT_EQ(shown.at("vertices"), std::to_string(expected.vertex_ids(0)) + "," +
                                      std::to_string(expected.vertex_ids(1)) +
                                      "," +
                                      std::to_string(expected.vertex_ids(2)));
  ASSERT_TRUE(expected.has_value());
  EXPECT_EQ(std::strtod(shown.at("value").c_str(), nullptr), expected.value());

  // The line's profile, as gRPC gives it for the same ends.
  grpc::ClientContext profile_context;
  v1::ProfileRequest line;
  line.set_dataset("terrain");
  line.set_crs("EPSG:4326");
  for (const std::string& end : {shown.at("from"), shown.at("to")}) {
    const Point2 p = PointOf(end);
    v1::Point* vertex = line.add_vertices();
    vertex->set_x(p.x);
    vertex->set_y(p.y);
  }
  v1::ProfileResponse profile;
  ASSERT_TRUE(stub->Profile(&profile_context, line, &profile).ok());
  EXPECT_GT(profile.crossings(), 10u);
  EXPECT_EQ(shown.at("crossings"), std::to_string(profile.crossings()));
  EXPECT_EQ(shown.at("breakpoints"),
            std::to_string(profile.breakpoints_size()));
  EXPECT_EQ(std::strtod(shown.at("length").c_str(), nullptr), profile.length());

  // The map as drawn: over the map's box (the window's left 720 x 540
  // pixels below the header), the relief's greys (the background and the
  // answers drawn over it are not grey) in dozens of levels over much of
  // it. Without the relief the box holds none.
  std::string png;
  ASSERT_TRUE(page->CaptureScreenshot(&png).ok());
  RgbaImage image;
  ASSERT_TRUE(DecodeRgbaPng(png, &image).ok());
  ASSERT_EQ(image.width, 1280u);
  ASSERT_GE(image.height, 620u);
  std::set<uint8_t> greys;
  size_t grey_pixels = 0, pixels = 0;
  for (uint32_t row = 80; row < 600; ++row) {
    for (uint32_t col = 30; col < 740; ++col) {
      const std::array<uint8_t, 3> rgb =
          image.Rgb(size_t{row} * image.width + col);
      ++pixels;
      if (rgb[0] != rgb[1] || rgb[1] != rgb[2]) continue;
      ++grey_pixels;
      greys.insert(rgb[0]);
    }
  }
  EXPECT_GT(greys.size(), 24u);
  EXPECT_GT(grey_pixels, pixels / 4);
  const std::filesystem::path artifact =
      std::filesystem::path(ARTIFACTS_DIR) / "web_map.png";
  std::filesystem::create_directories(artifact.parent_path());
  std::ofstream(artifact, std::ios::binary) << png;
}

}  // namespace
}  // namespace locator::test
