#include "common/gis/gdal_support.h"

#include <gdal.h>

#include <mutex>

#include "common/input_text.h"

namespace locator::gis {
namespace {

// `message` cut to kMaxGdalMessageBytes, or "no detail" if GDAL gave none.
std::string ShortMessage(const char* message) {
  return message != nullptr && *message != '\0'
             ? TruncatedMessage(message, kMaxGdalMessageBytes)
             : "no detail";
}

}  // namespace

void RegisterGdalDrivers() {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
}

std::string LastGdalError() { return ShortMessage(CPLGetLastErrorMsg()); }

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
  trap->failure_ = ShortMessage(message);
}

}  // namespace locator::gis
