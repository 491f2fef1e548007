// The coordinate reference system of a LAS file, as WKT2:
//   - from the OGC coordinate system WKT record ("LASF_Projection", record
//     2112, a VLR or an EVLR; LAS 1.4), else
//   - from the GeoTIFF keys ("LASF_Projection" records 34735, with the
//     double and ASCII parameters of 34736 and 34737 when keys point into
//     them), normalized by libgeotiff: the EPSG code of the projected or
//     geographic CRS when the keys name one, else the projection the keys
//     define parameter by parameter. Only the horizontal CRS is kept (a
//     vertical CS key is ignored: the values are the file's z as it is).
// A file with neither has no CRS (an empty string).
//
// Errors start with the file's name and name the record: InvalidArgument
// for a key directory whose sizes or references do not fit its records, an
// empty or unknown WKT, a geocentric model, or keys that define no CRS PROJ
// knows.
//
// Thread-safety: a free function; it uses the calling thread's PROJ context.

#ifndef LOCATOR_COMMON_GIS_LAS_LAS_CRS_H_
#define LOCATOR_COMMON_GIS_LAS_LAS_CRS_H_

#include <string>

#include "common/gis/las/las_header.h"
#include "common/gis/las/las_input.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis::las {

// The CRS of the file `header` was read from (see above), or "".
StatusOr<std::string> ReadLasCrs(const LasHeader& header, LasInput& input);

}  // namespace locator::gis::las

#endif  // LOCATOR_COMMON_GIS_LAS_LAS_CRS_H_
