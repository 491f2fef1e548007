// What every GDAL user in locator_gis needs: the drivers registered once per
// process, GDAL's last error message for a Status, and GdalErrorTrap, which
// keeps the failures GDAL reports while a read is under way.
//
// Thread-safety: the functions may be called from any thread (registration
// runs once; GDAL's error state and its handler stack are per thread). A
// GdalErrorTrap belongs to the thread that made it.

#ifndef LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
#define LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_

#include <cpl_error.h>

#include <cstddef>
#include <string>

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

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_GDAL_SUPPORT_H_
