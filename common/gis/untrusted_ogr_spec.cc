#include "common/gis/untrusted_ogr_spec.h"

#include <gdal.h>

#include <algorithm>
#include <array>

#include "common/gis/gdal_support.h"
#include "common/gis/request_crs_policy.h"
#include "common/gis/where_clause.h"

namespace locator::gis {
namespace {

constexpr std::array<const char*, 8> kVectorDrivers = {
    "GPKG",       "ESRI Shapefile",
    "GeoJSON",    "GeoJSONSeq",
    "FlatGeobuf", "CSV",
    "KML",        "GPX"};

// The open options (GDAL 3.6) of kVectorDrivers that a request may set. Left
// out: GPKG's PRELUDE_STATEMENTS (SQL) and its raster options (TABLE, WHERE,
// ...), Shapefile's AUTO_REPACK, DBF_DATE_LAST_UPDATE and DBF_EOF_CHAR
// (writing), GeoJSON's FEATURE_SERVER_PAGING (network).
constexpr std::array<std::string_view, 26> kOpenOptions = {
    // GPKG
    "LIST_ALL_TABLES", "IMMUTABLE", "NOLOCK",
    // ESRI Shapefile
    "ENCODING", "ADJUST_TYPE", "ADJUST_GEOM_TYPE",
    // GeoJSON
    "FLATTEN_NESTED_ATTRIBUTES", "NESTED_ATTRIBUTE_SEPARATOR", "NATIVE_DATA",
    "ARRAY_AS_STRING", "DATE_AS_STRING",
    // FlatGeobuf
    "VERIFY_BUFFERS",
    // CSV
    "MERGE_SEPARATOR", "AUTODETECT_TYPE", "KEEP_SOURCE_COLUMNS",
    "AUTODETECT_WIDTH", "AUTODETECT_SIZE_LIMIT", "QUOTED_FIELDS_AS_STRING",
    "X_POSSIBLE_NAMES", "Y_POSSIBLE_NAMES", "Z_POSSIBLE_NAMES",
    "GEOM_POSSIBLE_NAMES", "KEEP_GEOM_COLUMNS", "HEADERS",
    "EMPTY_STRING_AS_NULL", "MAX_LINE_SIZE"};

}  // namespace

Status CheckUntrustedOgrOptions(const OgrDatasetSpec& spec) {
  for (const std::string& option : spec.open_options) {
    std::string name = option.substr(0, option.find('='));
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return std::toupper(c); });
    if (std::find(kOpenOptions.begin(), kOpenOptions.end(), name) ==
        kOpenOptions.end()) {
      return Status::InvalidArgument(
          "oo=" + name.substr(0, 40) +
          ": not an open option a Reload may set (those that run SQL, name "
          "other files or reach the network are the operator's alone)");
    }
  }
  if (!spec.where.empty()) {
    if (Status status = CheckPlainWhereClause(spec.where); !status.ok()) {
      return Status::InvalidArgument("where=: " + status.message());
    }
  }
  if (!spec.assigned_crs.empty()) {
    if (Status status = CheckRequestCrs(spec.assigned_crs); !status.ok()) {
      return Status::InvalidArgument("a_srs=: " + status.message());
    }
  }
  return CheckUntrustedDriverName(spec.driver, kVectorDrivers);
}

Status UntrustedOgrDriver(const OgrDatasetSpec& spec, const std::string& path,
                          std::string* driver) {
  return ChooseUntrustedDriver(spec.driver, path, GDAL_OF_VECTOR,
                               kVectorDrivers, "format", driver);
}

}  // namespace locator::gis
