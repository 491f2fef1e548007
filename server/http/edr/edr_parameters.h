// The parameters of OGC API - EDR queries (OGC 19-086r6) that locatord's
// EDR routes read besides `coords` (wkt_coordinates.h): the output format
// `f` and the coordinate reference system `crs`, and the CRSs a
// collection offers.
//
// A collection (a dataset) with a CRS offers CRS84 (longitude, latitude)
// and its own CRS, named by its EPSG URI when it has an EPSG code; every
// collection offers its own coordinates as "dataset" (locator's name, the
// only one of a dataset without a CRS). `crs` absent: CRS84 where offered,
// else the dataset's own.
//
// Thread-safety: plain values and pure functions.

#ifndef LOCATOR_SERVER_HTTP_EDR_EDR_PARAMETERS_H_
#define LOCATOR_SERVER_HTTP_EDR_EDR_PARAMETERS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"

namespace locator {

inline constexpr char kCrs84Uri[] =
    "http://www.opengis.net/def/crs/OGC/1.3/CRS84";
// locator's name for a dataset's own coordinates.
inline constexpr char kDatasetCrsName[] = "dataset";

enum class EdrFormat { kCoverageJson, kGeoJson };

// The format `f` names: CoverageJSON (the default; also "covjson") or
// GeoJSON, case-insensitive. InvalidArgument naming the supported ones.
StatusOr<EdrFormat> ParseEdrFormat(std::optional<std::string_view> f);
// "CoverageJSON" or "GeoJSON".
std::string_view EdrFormatName(EdrFormat format);
// The answer's Content-Type.
std::string_view EdrContentType(EdrFormat format);

// One CRS a collection offers.
struct EdrCrs {
  // As the collection lists it and `crs=` names it.
  std::string uri;
  // The application's request CRS for it ("" the dataset's own).
  std::string request_crs;
  // Whether coordinates are longitude, latitude in degrees.
  bool lon_lat = false;
  // The WKT2 definition ("" for CRS84 and a dataset without a CRS).
  std::string wkt;
};

// The CRSs of a dataset whose statistics are `stats`, the default first.
std::vector<EdrCrs> OfferedCrs(const v1::DatasetStats& stats);

// The CRS `crs` names among `offered` (absent: the first). Besides the
// listed URIs, "CRS84", "OGC:CRS84" and "EPSG:<code>" are understood.
// InvalidArgument listing the offered ones.
StatusOr<EdrCrs> ParseEdrCrs(std::optional<std::string_view> crs,
                             const std::vector<EdrCrs>& offered);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_EDR_EDR_PARAMETERS_H_
