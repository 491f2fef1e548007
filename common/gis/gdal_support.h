// What every GDAL user in locator_gis needs: the drivers registered once per
// process, and GDAL's last error message for a Status.
//
// Thread-safety: both functions may be called from any thread (registration
// runs once; GDAL's error state is per thread).

#ifndef LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
#define LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_

#include <string>

namespace locator::gis {

// Registers GDAL's drivers (GDALAllRegister) the first time it is called.
void RegisterGdalDrivers();

// The message of the calling thread's last GDAL error, or "no detail" when
// GDAL left none.
std::string LastGdalError();

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
