#include "common/gis/gdal_support.h"

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

GdalErrorTrap::GdalErrorTrap() { CPLPushErrorHandlerEx(Handle, this); }

GdalErrorTrap::~GdalErrorTrap() { CPLPopErrorHandler(); }

std::string GdalErrorTrap::TakeFailure() {
  std::string failure;
  failure.swap(failure_);
  failed_ = false;
  return failure;
}

void CPL_STDCALL GdalErrorTrap::Handle(CPLErr level, CPLErrorNum /*number*/,
                                       const char* message) {
  auto* trap = static_cast<GdalErrorTrap*>(CPLGetErrorHandlerUserData());
  if (level < CE_Failure || trap == nullptr || trap->failed_) return;
  trap->failed_ = true;
  trap->failure_ =
      message != nullptr && *message != '\0' ? message : "no detail";
}

}  // namespace locator::gis
