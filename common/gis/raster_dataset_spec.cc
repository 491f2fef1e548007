#include "common/gis/raster_dataset_spec.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "common/status_macros.h"

namespace locator::gis {
namespace {

constexpr std::string_view kRasterPrefix = "raster:";
constexpr std::array<std::string_view, 10> kRasterExtensions = {
    ".tif", ".tiff", ".vrt", ".asc", ".img",
    ".dem", ".hgt",  ".bil", ".flt", ".grd"};

}  // namespace

bool IsRasterDatasetSpec(std::string_view spec) {
  return spec.starts_with(kRasterPrefix) ||
         SourceHasExtension(spec, kRasterExtensions);
}

SpecParts SplitRasterDatasetSpec(std::string_view spec) {
  return SplitSpec(spec, kRasterPrefix);
}

StatusOr<RasterDatasetSpec> ParseRasterDatasetSpec(std::string_view spec) {
  RasterDatasetSpec parsed;
  parsed.source = std::string(SplitRasterDatasetSpec(spec).source);
  if (parsed.source.empty())
    return SpecError(spec, "no source before the options");
  std::vector<SpecOption> options;
  RETURN_IF_ERROR(ParseSpecOptions(spec, &options));
  bool have_band = false;
  for (const SpecOption& option : options) {
    if (option.name == "band") {
      if (have_band) return SpecError(spec, "option 'band' given twice");
      have_band = true;
      uint64_t band = 0;
      RETURN_IF_ERROR(SpecOptionInteger(
          spec, option, 1, std::numeric_limits<int>::max(), &band));
      parsed.band = static_cast<int>(band);
    } else if (option.name == "a_srs" || option.name == "driver") {
      std::string& field =
          option.name == "a_srs" ? parsed.assigned_crs : parsed.driver;
      if (!field.empty()) {
        return SpecError(spec, "option '" + option.name + "' given twice");
      }
      if (option.value.empty()) {
        return SpecError(spec, "option '" + option.name + "' is empty");
      }
      field = option.value;
    } else {
      return UnknownSpecOption(spec, option.name, "band, a_srs, driver");
    }
  }
  return parsed;
}

}  // namespace locator::gis
