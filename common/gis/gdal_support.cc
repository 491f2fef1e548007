#include "common/gis/gdal_support.h"

#include <cpl_error.h>
#include <gdal.h>

#include <mutex>

namespace locator::gis {

void RegisterGdalDrivers() {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
}

std::string LastGdalError() {
  const char* message = CPLGetLastErrorMsg();
  return message != nullptr && *message != '\0' ? message : "no detail";
}

}  // namespace locator::gis
