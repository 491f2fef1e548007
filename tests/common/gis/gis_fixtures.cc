#include "tests/common/gis/gis_fixtures.h"

#include <cpl_conv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <fstream>
#include <sstream>

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
