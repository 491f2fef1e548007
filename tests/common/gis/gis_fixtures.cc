#include "tests/common/gis/gis_fixtures.h"

#include <cpl_conv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>

#include "tests/testing/run_binary.h"

namespace locator::gis::testing {

void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

std::string GeometriesGeoJson(const std::vector<std::string>& geometries) {
  std::string out = R"({"type":"FeatureCollection","features":[)";
  for (size_t i = 0; i < geometries.size(); ++i) {
    out += (i == 0 ? "" : ",");
    out += R"({"type":"Feature","properties":{"id":)" + std::to_string(i) +
           R"(},"geometry":)" + geometries[i] + "}";
  }
  return out + "]}";
}

std::string PointsGeoJson(const std::vector<PointZ>& points) {
  std::ostringstream out;
  out.precision(17);
  out << R"({"type":"FeatureCollection","features":[)";
  for (size_t i = 0; i < points.size(); ++i) {
    const PointZ& p = points[i];
    out << (i == 0 ? "" : ",") << R"({"type":"Feature","properties":{"id":)"
        << i << R"(,"height":)" << p.z
        << R"(},"geometry":{"type":"Point","coordinates":[)" << p.x << ","
        << p.y << "," << p.z << "]}}";
  }
  out << "]}";
  return out.str();
}

std::string RunTool(const std::string& program,
                    const std::vector<std::string>& args) {
  const locator::test::BinaryResult result =
      locator::test::RunBinary(program, args);
  EXPECT_EQ(result.exit_code, 0) << program << " failed: " << result.err;
  return result.out;
}

void Ogr2Ogr(const std::vector<std::string>& args) {
  RunTool(OGR2OGR_PATH, args);
}

std::string UtmHillGeoPackage(int n, const std::string& dir) {
  const std::string geojson = dir + "/hill.geojson";
  WriteFile(geojson, PointsGeoJson(UtmHill(n)));
  const std::string gpkg = dir + "/hill.gpkg";
  Ogr2Ogr(
      {"-f", "GPKG", gpkg, geojson, "-nln", "hill", "-a_srs", "EPSG:32633"});
  return gpkg;
}

int CorruptMiddleDataPage(const std::string& gpkg) {
  std::string bytes;
  {
    std::ifstream in(gpkg, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // The SQLite file format: the page size (big-endian, 1 for 65536) at
  // byte 16; a page's b-tree header first (after the 100-byte file header
  // on page 1), type 0x0D for a table leaf.
  EXPECT_GT(bytes.size(), 100u) << gpkg;
  if (bytes.size() <= 100) return 0;
  const unsigned raw = static_cast<unsigned char>(bytes[16]) << 8 |
                       static_cast<unsigned char>(bytes[17]);
  const size_t page_size = raw == 1 ? 65536 : raw;
  constexpr std::string_view kGeometryBlob("GP\0", 3);
  std::vector<size_t> data_pages;  // 0-based
  for (size_t page = 1; (page + 1) * page_size <= bytes.size(); ++page) {
    const std::string_view content(bytes.data() + page * page_size, page_size);
    if (content[0] == 0x0D && content.find(kGeometryBlob) != content.npos) {
      data_pages.push_back(page);
    }
  }
  EXPECT_GE(data_pages.size(), 3u) << gpkg << ": too few data pages";
  if (data_pages.empty()) return 0;
  const size_t page = data_pages[data_pages.size() / 2];
  std::fill_n(bytes.begin() + page * page_size, 8, '\xff');
  std::ofstream(gpkg, std::ios::binary | std::ios::trunc) << bytes;
  return static_cast<int>(page + 1);
}

std::string EpsgWkt2(int code) {
  OGRSpatialReference crs;
  EXPECT_EQ(crs.importFromEPSG(code), OGRERR_NONE) << code;
  char* wkt = nullptr;
  const char* const options[] = {"FORMAT=WKT2", nullptr};
  EXPECT_EQ(crs.exportToWkt(&wkt, options), OGRERR_NONE) << code;
  const std::string text = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  return text;
}

std::vector<Point2> Cs2cs(const std::vector<Point2>& points,
                          const std::string& from, const std::string& to,
                          const std::string& dir) {
  const bool lat_lon_in = from == "EPSG:4326", lat_lon_out = to == "EPSG:4326";
  std::ostringstream input;
  input.precision(17);
  for (const Point2& p : points) {
    input << (lat_lon_in ? p.y : p.x) << " " << (lat_lon_in ? p.x : p.y)
          << "\n";
  }
  const std::string path = dir + "/cs2cs_input.txt";
  WriteFile(path, input.str());
  std::istringstream output(
      RunTool(CS2CS_PATH, {"-f", "%.12f", from, to, path}));
  std::vector<Point2> out;
  double a, b, height;
  while (output >> a >> b >> height) {
    out.push_back(lat_lon_out ? Point2{b, a} : Point2{a, b});
  }
  EXPECT_EQ(out.size(), points.size());
  return out;
}

std::vector<PointZ> UtmHill(int n) {
  constexpr double kCenterX = 500000, kCenterY = 5500000;
  constexpr double kSpacing = 400, kSigma = 1500;
  std::vector<PointZ> points;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      // A small deterministic jitter keeps the grid from being cocircular.
      const double x = kCenterX + (i - n / 2) * kSpacing + (j % 3) * 7.0;
      const double y = kCenterY + (j - n / 2) * kSpacing + (i % 5) * 5.0;
      const double r2 =
          (x - kCenterX) * (x - kCenterX) + (y - kCenterY) * (y - kCenterY);
      points.push_back(
          {x, y, 400 + 300 * std::exp(-r2 / (2 * kSigma * kSigma))});
    }
  }
  return points;
}

}  // namespace locator::gis::testing
