#include "server/http/edr/edr_parameters.h"

#include <cctype>
#include <string>

#include "common/input_text.h"
#include "server/http/elevation/elevation_calls.h"

namespace locator {
namespace {

constexpr std::string_view kEpsgUriPrefix =
    "http://www.opengis.net/def/crs/EPSG/0/";

bool EqualsIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

}  // namespace

StatusOr<EdrFormat> ParseEdrFormat(std::optional<std::string_view> f) {
  if (!f.has_value() || EqualsIgnoringCase(*f, "CoverageJSON") ||
      EqualsIgnoringCase(*f, "covjson")) {
    return EdrFormat::kCoverageJson;
  }
  if (EqualsIgnoringCase(*f, "GeoJSON")) return EdrFormat::kGeoJson;
  return Status::InvalidArgument("f: unsupported output format " +
                                 QuotedInput(*f) +
                                 "; this server answers CoverageJSON (the "
                                 "default) or GeoJSON");
}

std::string_view EdrFormatName(EdrFormat format) {
  return format == EdrFormat::kGeoJson ? "GeoJSON" : "CoverageJSON";
}

std::string_view EdrContentType(EdrFormat format) {
  return format == EdrFormat::kGeoJson ? "application/geo+json"
                                       : "application/prs.coverage+json";
}

std::vector<EdrCrs> OfferedCrs(const v1::DatasetStats& stats) {
  std::vector<EdrCrs> offered;
  if (stats.has_crs()) {
    offered.push_back(EdrCrs{.uri = kCrs84Uri,
                             .request_crs = kLonLatCrs,
                             .lon_lat = true,
                             .wkt = ""});
    const bool degrees = stats.crs().axis_units_size() > 0 &&
                         stats.crs().axis_units(0) == "degree";
    if (stats.crs().epsg_code() != 0) {
      offered.push_back(EdrCrs{.uri = std::string(kEpsgUriPrefix) +
                                      std::to_string(stats.crs().epsg_code()),
                               .request_crs = "",
                               .lon_lat = degrees,
                               .wkt = stats.crs().wkt()});
    }
    offered.push_back(EdrCrs{.uri = kDatasetCrsName,
                             .request_crs = "",
                             .lon_lat = degrees,
                             .wkt = stats.crs().wkt()});
  } else {
    offered.push_back(EdrCrs{.uri = kDatasetCrsName,
                             .request_crs = "",
                             .lon_lat = false,
                             .wkt = ""});
  }
  return offered;
}

StatusOr<EdrCrs> ParseEdrCrs(std::optional<std::string_view> crs,
                             const std::vector<EdrCrs>& offered) {
  if (!crs.has_value()) return offered.front();
  std::string uri(*crs);
  if (EqualsIgnoringCase(uri, "CRS84") ||
      EqualsIgnoringCase(uri, "OGC:CRS84")) {
    uri = kCrs84Uri;
  } else if (uri.size() > 5 && EqualsIgnoringCase(uri.substr(0, 5), "EPSG:")) {
    uri = std::string(kEpsgUriPrefix) + uri.substr(5);
  }
  std::string names;
  for (const EdrCrs& candidate : offered) {
    if (candidate.uri == uri) return candidate;
    names += (names.empty() ? "" : ", ") + candidate.uri;
  }
  return Status::InvalidArgument("crs: " + QuotedInput(*crs) +
                                 " is not a CRS of this collection; it "
                                 "offers " +
                                 names);
}

}  // namespace locator
