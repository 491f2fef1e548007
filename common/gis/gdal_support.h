// What every GDAL user in locator_gis needs: the drivers registered once per
// process, GDAL's last error message for a Status, CRSs as WKT and the files
// a dataset reads.
//
// Thread-safety: both functions may be called from any thread (registration
// runs once; GDAL's error state is per thread).

#ifndef LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
#define LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_

#include <string>
#include <vector>

#include "common/status.h"

class GDALDataset;
class OGRSpatialReference;

namespace locator::gis {

// Registers GDAL's drivers (GDALAllRegister) the first time it is called.
void RegisterGdalDrivers();

// The message of the calling thread's last GDAL error, or "no detail" when
// GDAL left none.
std::string LastGdalError();

// `srs` as WKT2 (2019).
std::string SpatialRefToWkt(const OGRSpatialReference& srs);

// The CRS `crs` names (EPSG:NNNN, WKT or a PROJ string, as gdal_translate
// -a_srs takes it) as WKT2, read without file or network access.
// InvalidArgument "unknown CRS '...'" with GDAL's message otherwise.
Status UserCrsToWkt(const std::string& crs, std::string* wkt);

// The files `dataset` reads (GDALDataset::GetFileList: the main file and
// its side-cars, a VRT's sources), in GDAL's order.
std::vector<std::string> GdalFileList(GDALDataset& dataset);

// GdalFileList of the vector source `source` opened with `open_options`
// (NAME=VALUE each), without reading a feature. InvalidArgument with GDAL's
// message when GDAL cannot open it.
Status VectorFileList(const std::string& source,
                      const std::vector<std::string>& open_options,
                      std::vector<std::string>* files);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
