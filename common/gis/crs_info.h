// CrsInfo: what stats say about a dataset's coordinate reference system.
//
// Thread-safety: both functions may be called from any thread (they use
// the calling thread's PROJ context; the memo is guarded by a mutex); a
// CrsInfo is a plain value.

#ifndef LOCATOR_COMMON_GIS_CRS_INFO_H_
#define LOCATOR_COMMON_GIS_CRS_INFO_H_

#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis {

struct CrsInfo {
  // PROJ's name of the CRS ("WGS 84 / UTM zone 33N").
  std::string name;
  // The EPSG code when the CRS carries one or PROJ identifies it with full
  // confidence; 0 otherwise.
  int epsg_code = 0;
  // The unit of each horizontal axis, in traditional GIS order (x first):
  // {"metre", "metre"}, {"degree", "degree"}.
  std::vector<std::string> axis_units;
};

// Describes the CRS `crs` names (EPSG:NNNN, WKT or a PROJ string);
// InvalidArgument naming it when PROJ does not know it.
StatusOr<CrsInfo> DescribeCrs(std::string_view crs);

// DescribeCrs, memoized process-wide for the few most recent CRSs
// (identifying a WKT without an ID takes milliseconds), for stats.
StatusOr<CrsInfo> DescribeCrsMemoized(const std::string& crs);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_CRS_INFO_H_
