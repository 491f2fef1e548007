// What every GDAL user in locator_gis needs: the drivers registered once per
// process, GDAL's last error message for a Status, GdalErrorTrap, which
// keeps the failures GDAL reports while a read is under way, CRSs as WKT and
// the files a dataset reads.
//
// Thread-safety: the functions may be called from any thread (registration
// runs once; GDAL's error state and its handler stack are per thread). A
// GdalErrorTrap belongs to the thread that made it.

#ifndef LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
#define LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_

#include <cpl_error.h>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"
#include "locator/status_or.h"

class GDALDataset;
class OGRSpatialReference;

namespace locator::gis {

// Registers GDAL's drivers (GDALAllRegister) the first time it is called.
void RegisterGdalDrivers();

// The most of a GDAL message a Status shows: GDAL quotes what it could not
// use (a where clause, a field) whole.
inline constexpr size_t kMaxGdalMessageBytes = 256;

// The message of the calling thread's last GDAL error (cut to
// kMaxGdalMessageBytes), or "no detail" when GDAL left none.
std::string LastGdalError();

// While it lives, GDAL's errors on this thread come here instead of stderr:
// it keeps the first failure (CE_Failure or CE_Fatal) and drops warnings.
// GDAL's drivers report a failed read this way and then carry on or end
// the layer early, as if it ended there: a reader must look.
class GdalErrorTrap {
 public:
  GdalErrorTrap();
  ~GdalErrorTrap();
  GdalErrorTrap(const GdalErrorTrap&) = delete;
  GdalErrorTrap& operator=(const GdalErrorTrap&) = delete;

  // The first failure's message (cut to kMaxGdalMessageBytes) since
  // construction or the last call, or "" if there was none; forgets it.
  std::string TakeFailure();

 private:
  static void CPL_STDCALL Handle(CPLErr level, CPLErrorNum number,
                                 const char* message);

  std::string failure_;
  bool failed_ = false;
};

// `srs` as WKT2 (2019).
std::string SpatialRefToWkt(const OGRSpatialReference& srs);

// The CRS `crs` names (EPSG:NNNN, WKT or a PROJ string, as gdal_translate
// -a_srs takes it) as WKT2, read without file or network access.
// InvalidArgument "unknown CRS '...'" (QuotedCrs) with GDAL's message
// otherwise.
StatusOr<std::string> UserCrsToWkt(const std::string& crs);

// The files `dataset` reads (GDALDataset::GetFileList: the main file and
// its side-cars, a VRT's sources), in GDAL's order.
std::vector<std::string> GdalFileList(GDALDataset& dataset);

// The short name of the driver among `drivers` that identifies `path` as a
// dataset of `kind` (GDAL_OF_VECTOR or GDAL_OF_RASTER), quietly; "" when
// none of them does.
std::string IdentifyDriverAmong(const std::string& path, unsigned kind,
                                std::span<const char* const> drivers);

// `drivers` as "A, B, C".
std::string DriverNames(std::span<const char* const> drivers);

// OK if `requested` is empty or one of `drivers`; InvalidArgument
// "driver='NAME': a Reload may read only DRIVERS" otherwise.
Status CheckUntrustedDriverName(const std::string& requested,
                                std::span<const char* const> drivers);

// The driver a request's file at `path` is to be read with: `requested`
// when the request names one (checked against `drivers` before), else the
// one among `drivers` IdentifyDriverAmong finds. InvalidArgument "not a
// FORMAT a Reload may read (DRIVERS)" when none of them does.
Status ChooseUntrustedDriver(const std::string& requested,
                             const std::string& path, unsigned kind,
                             std::span<const char* const> drivers,
                             std::string_view format, std::string* driver);

// GdalFileList of the vector source `source` opened with `open_options`
// (NAME=VALUE each) by `driver` (a short name; "" for any), without reading
// a feature. InvalidArgument with GDAL's message when GDAL cannot open it.
Status VectorFileList(const std::string& source,
                      const std::vector<std::string>& open_options,
                      const std::string& driver,
                      std::vector<std::string>* files);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
