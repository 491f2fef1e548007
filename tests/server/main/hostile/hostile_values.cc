#include "tests/server/main/hostile/hostile_values.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace locator::test {
namespace {

constexpr uint64_t kDefaultSeed = 26;
// 64 times the request CRS limit and 128 times gRPC's 8 KiB metadata limit,
// which an echo of it would overflow (bad_input_table_test sends the
// issue's 10 MiB once).
constexpr size_t kHugeCrsBytes = size_t{1} << 20;
constexpr size_t kLongNameBytes = size_t{1} << 20;

// `text` with every "%FILE%" replaced by `file`.
std::string NamingFile(std::string text, const std::string& file) {
  const std::string marker = "%FILE%";
  for (size_t at = text.find(marker); at != std::string::npos;
       at = text.find(marker, at + file.size())) {
    text.replace(at, marker.size(), file);
  }
  return text;
}

// A WKT1 CRS whose datum names `%FILE%` as its grid (GDAL's PROJ4_GRIDS).
constexpr char kWkt1Grids[] =
    R"(GEOGCS["unknown",DATUM["grid",SPHEROID["WGS 84",6378137,)"
    R"(298.257223563],EXTENSION["PROJ4_GRIDS","%FILE%"]],)"
    R"(PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]])";
// A WKT2 BOUNDCRS whose transformation reads `%FILE%`.
constexpr char kWkt2ParameterFile[] =
    R"(BOUNDCRS[SOURCECRS[GEOGCRS["unknown",DATUM["grid",ELLIPSOID["WGS 84",)"
    R"(6378137,298.257223563]],CS[ellipsoidal,2],AXIS["longitude",east],)"
    R"(AXIS["latitude",north],ANGLEUNIT["degree",0.0174532925199433]]],)"
    R"(TARGETCRS[GEOGCRS["WGS 84",DATUM["World Geodetic System 1984",)"
    R"(ELLIPSOID["WGS 84",6378137,298.257223563]],CS[ellipsoidal,2],)"
    R"(AXIS["latitude",north],AXIS["longitude",east],)"
    R"(ANGLEUNIT["degree",0.0174532925199433],ID["EPSG",4326]]],)"
    R"(ABRIDGEDTRANSFORMATION["grid to WGS84",METHOD["NTv2",ID["EPSG",9615]],)"
    R"(PARAMETERFILE["Latitude and longitude difference file","%FILE%"]]])";
// The same as PROJJSON.
constexpr char kProjJsonParameterFile[] =
    R"({"type":"BoundCRS","source_crs":{"type":"GeographicCRS","name":"x",)"
    R"("datum":{"type":"GeodeticReferenceFrame","name":"grid","ellipsoid":)"
    R"({"name":"WGS 84","semi_major_axis":6378137,"inverse_flattening":)"
    R"(298.257223563}},"coordinate_system":{"subtype":"ellipsoidal","axis":)"
    R"([{"name":"Longitude","abbreviation":"lon","direction":"east","unit":)"
    R"("degree"},{"name":"Latitude","abbreviation":"lat","direction":)"
    R"("north","unit":"degree"}]}},"target_crs":{"type":"GeographicCRS",)"
    R"("name":"WGS 84","datum":{"type":"GeodeticReferenceFrame","name":)"
    R"("World Geodetic System 1984","ellipsoid":{"name":"WGS 84",)"
    R"("semi_major_axis":6378137,"inverse_flattening":298.257223563}},)"
    R"("coordinate_system":{"subtype":"ellipsoidal","axis":[{"name":)"
    R"("Latitude","abbreviation":"lat","direction":"north","unit":"degree"},)"
    R"({"name":"Longitude","abbreviation":"lon","direction":"east","unit":)"
    R"("degree"}]},"id":{"authority":"EPSG","code":4326}},"transformation":)"
    R"({"name":"grid to WGS84","method":{"name":"NTv2"},"parameters":)"
    R"([{"name":"Latitude and longitude difference file","value":"%FILE%"}]}})";
// A valid geographic CRS as PROJJSON (lon, lat axes).
constexpr char kProjJsonLonLat[] =
    R"({"type":"GeographicCRS","name":"WGS 84 lon/lat","datum":{"type":)"
    R"("GeodeticReferenceFrame","name":"World Geodetic System 1984",)"
    R"("ellipsoid":{"name":"WGS 84","semi_major_axis":6378137,)"
    R"("inverse_flattening":298.257223563}},"coordinate_system":{"subtype":)"
    R"("ellipsoidal","axis":[{"name":"Longitude","abbreviation":"lon",)"
    R"("direction":"east","unit":"degree"},{"name":"Latitude",)"
    R"("abbreviation":"lat","direction":"north","unit":"degree"}]}})";

uint64_t FromEnvironment(const char* name, uint64_t fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  return std::strtoull(text, nullptr, 0);
}

}  // namespace

const std::vector<double>& HostileCoordinates() {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const std::vector<double> values = {
      0.0,
      -0.0,
      4.9e-324,
      -4.9e-324,
      2.2e-308,
      -2.2e-308,
      1e-300,
      -1e-300,
      1e150,
      -1e150,
      1e160,
      -1e160,
      1e300,
      -1e300,
      kMax,
      -kMax,
      std::numeric_limits<double>::quiet_NaN(),
      kInf,
      -kInf};
  return values;
}

std::string DoubleName(double v) {
  if (v == 0) return std::signbit(v) ? "-0" : "0";
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

std::vector<RequestCrs> RequestCrsList(const std::string& fifo,
                                       const std::string& secret,
                                       const std::string& utm_wkt2,
                                       const std::string& lon_lat_wkt2) {
  const std::string longlat = "+proj=longlat +ellps=WGS84 ";
  std::vector<RequestCrs> list = {
      {"EPSG:32633", "EPSG:32633", CrsKind::kDatasetOwn},
      {"WKT2 of EPSG:32633", utm_wkt2, CrsKind::kDatasetOwn},
      {"EPSG:4326", "EPSG:4326", CrsKind::kLonLat},
      {"WKT2 of EPSG:4326", lon_lat_wkt2, CrsKind::kLonLat},
      {"PROJJSON lon/lat", kProjJsonLonLat, CrsKind::kLonLat},
      {"+proj=longlat", longlat + "+no_defs", CrsKind::kLonLat},
      {"+init=epsg:4326", "+init=epsg:4326", CrsKind::kMaybe},
      {"optional grid @/dev/ptmx", longlat + "+nadgrids=@/dev/ptmx",
       CrsKind::kMaybe},
      {"absurd towgs84",
       longlat + "+towgs84=1e300,-1e300,1e300,1e160,1e160,1e160,1e300",
       CrsKind::kMaybe},
      {"UTM zone 1e300", "+proj=utm +zone=1e300 +ellps=WGS84",
       CrsKind::kRefused},
  };
  for (const std::string& file :
       {std::string("/dev/ptmx"), fifo, std::string("/dev/zero"), secret}) {
    list.push_back({"+nadgrids=" + file, longlat + "+nadgrids=" + file,
                    CrsKind::kRefused});
    list.push_back(
        {"+init=" + file, "+init=" + file + ":4326", CrsKind::kRefused});
    // Grids a 2D transform may do without (a vertical grid) or that PROJ
    // may replace by a ballpark transformation: answered or refused, but
    // never read (the test watches `secret`) and never waited on.
    list.push_back({"+geoidgrids=" + file,
                    longlat + "+geoidgrids=" + file + " +vunits=m",
                    CrsKind::kMaybe});
    list.push_back(
        {"WKT1 grids " + file, NamingFile(kWkt1Grids, file), CrsKind::kMaybe});
    list.push_back({"WKT2 parameter file " + file,
                    NamingFile(kWkt2ParameterFile, file), CrsKind::kMaybe});
    list.push_back({"PROJJSON parameter file " + file,
                    NamingFile(kProjJsonParameterFile, file), CrsKind::kMaybe});
    list.push_back({"a path " + file, file, CrsKind::kRefused});
  }
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"unknown EPSG", "EPSG:999999"},
      {"EPSG:0", "EPSG:0"},
      {"EPSG beyond 32 bits", "EPSG:4294967297"},
      {"unknown ESRI", "ESRI:999999"},
      {"unknown authority", "NOPE:4326"},
      {"operation EPSG:1671", "EPSG:1671"},
      {"operation URN", "urn:ogc:def:coordinateOperation:EPSG::1671"},
      {"operation pipeline",
       "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad"},
      {"conversion only", "+proj=utm +zone=33"},
      {"garbage", "}{][\"\\ \t \x7f"},
      {"unterminated WKT", "GEOGCS[\"x\",DATUM["},
      {"unterminated PROJJSON", "{\"type\":\"GeographicCRS\",\"name\":"},
      {"empty +proj", "+proj="},
      {"whitespace", "   "},
  };
  for (const auto& [label, text] : refused) {
    list.push_back({label, text, CrsKind::kRefused});
  }
  list.push_back(
      {"1 MiB of 'A'", std::string(kHugeCrsBytes, 'A'), CrsKind::kHuge});
  std::string huge_code = "EPSG:" + std::string(kHugeCrsBytes, '9');
  list.push_back({"EPSG: and 1 MiB of digits", huge_code, CrsKind::kHuge});
  return list;
}

std::vector<std::string> HostileDatasetNames() {
  return {"nope",
          "../plain",
          "plain/../utm",
          "plain\n",
          "plain\t",
          "UTM",
          "%2e%2e",
          "plain?x=1",
          "\xc3\xbcmlaut",
          "a b",
          std::string(kLongNameBytes, 'n')};
}

std::vector<Focus> Coverage(std::span<const size_t> values_per_field,
                            int repeats, uint64_t seed) {
  std::vector<Focus> pairs;
  for (int r = 0; r < repeats; ++r) {
    for (size_t field = 0; field < values_per_field.size(); ++field) {
      for (size_t value = 0; value < values_per_field[field]; ++value) {
        pairs.push_back({static_cast<int>(field), value});
      }
    }
  }
  std::mt19937_64 rng(seed);
  std::shuffle(pairs.begin(), pairs.end(), rng);
  return pairs;
}

CaseDraw::CaseDraw(uint64_t seed, size_t case_index, Focus focus,
                   double company_rate)
    : focus_(focus),
      company_rate_(company_rate),
      rng_(seed * 0x9E3779B97F4A7C15ull + case_index) {}

std::optional<size_t> CaseDraw::Hostile(int field, size_t count) {
  if (field == focus_.field) return focus_.value;
  if (count == 0 || !Chance(company_rate_)) return std::nullopt;
  return Below(count);
}

bool CaseDraw::Chance(double p) { return std::bernoulli_distribution(p)(rng_); }

size_t CaseDraw::Below(size_t n) {
  return std::uniform_int_distribution<size_t>(0, n - 1)(rng_);
}

double CaseDraw::Uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng_);
}

double CaseDraw::HostileCoordinate() {
  return HostileCoordinates()[Below(HostileCoordinates().size())];
}

uint64_t HostileSeed() {
  return FromEnvironment("LOCATOR_HOSTILE_SEED", kDefaultSeed);
}

int HostileRepeats() {
  return static_cast<int>(FromEnvironment("LOCATOR_HOSTILE_REPEATS", 1));
}

}  // namespace locator::test
