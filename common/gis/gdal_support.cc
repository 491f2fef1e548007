#include "common/gis/gdal_support.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <mutex>

#include "common/gis/proj_objects.h"
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

std::string SpatialRefToWkt(const OGRSpatialReference& srs) {
  char* wkt = nullptr;
  const char* const options[] = {"FORMAT=WKT2_2019", nullptr};
  srs.exportToWkt(&wkt, options);
  std::string out = wkt == nullptr ? "" : wkt;
  CPLFree(wkt);
  return out;
}

StatusOr<std::string> UserCrsToWkt(const std::string& crs) {
  OGRSpatialReference srs;
  const char* const options[] = {"ALLOW_NETWORK_ACCESS=NO",
                                 "ALLOW_FILE_ACCESS=NO", nullptr};
  CPLErrorReset();
  if (srs.SetFromUserInput(crs.c_str(), options) != OGRERR_NONE) {
    return Status::InvalidArgument("unknown CRS " + QuotedCrs(crs) + ": " +
                                   LastGdalError());
  }
  return SpatialRefToWkt(srs);
}

std::vector<std::string> GdalFileList(GDALDataset& dataset) {
  std::vector<std::string> files;
  char** list = dataset.GetFileList();
  for (char** file = list; file != nullptr && *file != nullptr; ++file) {
    files.emplace_back(*file);
  }
  CSLDestroy(list);
  return files;
}

std::string IdentifyDriverAmong(const std::string& path, unsigned kind,
                                std::span<const char* const> drivers) {
  RegisterGdalDrivers();
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  std::vector<const char*> allowed(drivers.begin(), drivers.end());
  allowed.push_back(nullptr);
  GDALDriverH found =
      GDALIdentifyDriverEx(path.c_str(), kind, allowed.data(), nullptr);
  return found == nullptr ? "" : GDALGetDriverShortName(found);
}

std::string DriverNames(std::span<const char* const> drivers) {
  std::string list;
  for (const char* driver : drivers) {
    list += (list.empty() ? "" : ", ") + std::string(driver);
  }
  return list;
}

Status CheckUntrustedDriverName(const std::string& requested,
                                std::span<const char* const> drivers) {
  if (requested.empty() ||
      std::any_of(drivers.begin(), drivers.end(),
                  [&](const char* d) { return requested == d; })) {
    return Status::OK();
  }
  return Status::InvalidArgument("driver=" + QuotedInput(requested) +
                                 ": a Reload may read only " +
                                 DriverNames(drivers));
}

Status ChooseUntrustedDriver(const std::string& requested,
                             const std::string& path, unsigned kind,
                             std::span<const char* const> drivers,
                             std::string_view format, std::string* driver) {
  *driver =
      requested.empty() ? IdentifyDriverAmong(path, kind, drivers) : requested;
  if (driver->empty()) {
    return Status::InvalidArgument("not a " + std::string(format) +
                                   " a Reload may read (" +
                                   DriverNames(drivers) + ")");
  }
  return Status::OK();
}

Status VectorFileList(const std::string& source,
                      const std::vector<std::string>& open_options,
                      const std::string& driver,
                      std::vector<std::string>* files) {
  RegisterGdalDrivers();
  std::vector<const char*> options;
  for (const std::string& option : open_options)
    options.push_back(option.c_str());
  options.push_back(nullptr);
  const char* const only_driver[] = {driver.c_str(), nullptr};
  CPLErrorReset();
  GDALDatasetUniquePtr dataset(GDALDataset::Open(
      source.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
      driver.empty() ? nullptr : only_driver, options.data(), nullptr));
  if (dataset == nullptr) {
    return Status::InvalidArgument(source +
                                   ": GDAL cannot open it: " + LastGdalError());
  }
  *files = GdalFileList(*dataset);
  return Status::OK();
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
  trap->failure_ = ShortMessage(message);
}

}  // namespace locator::gis
