#include "common/gis/untrusted_raster_spec.h"

#include <gdal.h>

#include <array>

#include "common/gis/gdal_support.h"
#include "common/gis/request_crs_policy.h"
#include "common/input_text.h"

namespace locator::gis {
namespace {

constexpr std::array<const char*, 8> kRasterDrivers = {
    "GTiff", "AAIGrid", "EHdr", "SRTMHGT", "USGSDEM", "GSAG", "GSBG", "GS7BG"};

}  // namespace

Status CheckUntrustedRasterOptions(const RasterDatasetSpec& spec) {
  if (!spec.assigned_crs.empty()) {
    if (Status status = CheckRequestCrs(spec.assigned_crs); !status.ok()) {
      return Status::InvalidArgument("a_srs=: " + status.message());
    }
  }
  return CheckUntrustedDriverName(spec.driver, kRasterDrivers);
}

Status UntrustedRasterDriver(const RasterDatasetSpec& spec,
                             const std::string& path, std::string* driver) {
  return ChooseUntrustedDriver(spec.driver, path, GDAL_OF_RASTER,
                               kRasterDrivers, "raster format", driver);
}

}  // namespace locator::gis
