#include "tests/server/http/elevation/elevation_e2e_support.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "common/input_text.h"

namespace locator::test {

// Google's Encoded Polyline Algorithm Format, for the test's own requests.
std::string EncodePolyline(const std::vector<Point2>& lng_lat) {
  std::string encoded;
  int64_t previous_lat = 0;
  int64_t previous_lng = 0;
  const auto put = [&encoded](int64_t delta) {
    uint64_t bits = delta < 0 ? ~(static_cast<uint64_t>(delta) << 1)
                              : static_cast<uint64_t>(delta) << 1;
    while (bits >= 0x20) {
      encoded.push_back(static_cast<char>((0x20 | (bits & 0x1f)) + 63));
      bits >>= 5;
    }
    encoded.push_back(static_cast<char>(bits + 63));
  };
  for (const Point2& p : lng_lat) {
    const int64_t lat = std::llround(p.y * 1e5);
    const int64_t lng = std::llround(p.x * 1e5);
    put(lat - previous_lat);
    put(lng - previous_lng);
    previous_lat = lat;
    previous_lng = lng;
  }
  return encoded;
}

// "lat,lng|lat,lng", each number exactly.
std::string LatLngs(const std::vector<Point2>& lng_lat) {
  std::string text;
  for (const Point2& p : lng_lat) {
    if (!text.empty()) text += "|";
    text += NumberText(p.y) + "," + NumberText(p.x);
  }
  return text;
}

// `text` with the characters a URL's query may not carry escaped.
std::string UrlEscaped(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ||
        c == ',' || c == '_') {
      escaped.push_back(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof(hex), "%%%02X", static_cast<unsigned char>(c));
      escaped += hex;
    }
  }
  return escaped;
}

// "x y, x y".
std::string WktPoints(const std::vector<Point2>& points, bool parenthesized) {
  std::string text;
  for (const Point2& p : points) {
    if (!text.empty()) text += ",";
    const std::string pair = NumberText(p.x) + " " + NumberText(p.y);
    text += parenthesized ? "(" + pair + ")" : pair;
  }
  return text;
}

// GETs `target`, a CoverageJSON answer, and parses it; a failure is a test
// failure and yields null.
JsonValue GetCoverage(int port, const std::string& target) {
  HttpReply reply;
  JsonValue coverage;
  EXPECT_TRUE(HttpGet(port, target, &reply).ok());
  EXPECT_EQ(reply.status, 200u) << target << ": " << reply.body;
  EXPECT_EQ(reply.headers["content-type"], "application/prs.coverage+json");
  EXPECT_TRUE(ParseJson(reply.body, &coverage).ok()) << reply.body;
  return coverage;
}

ScratchDir* ElevationE2eTest::dir_ = nullptr;
std::unique_ptr<LocatordWithHttp> ElevationE2eTest::server_;

}  // namespace locator::test
