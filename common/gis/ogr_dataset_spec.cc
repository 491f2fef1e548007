#include "common/gis/ogr_dataset_spec.h"

#include <array>
#include <utility>

#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

constexpr std::string_view kOgrPrefix = "ogr:";
constexpr std::array<std::string_view, 9> kOgrExtensions = {
    ".gpkg", ".shp", ".geojson", ".json", ".fgb",
    ".gml",  ".kml", ".sqlite",  ".gpx"};

}  // namespace

bool IsOgrDatasetSpec(std::string_view spec) {
  return spec.starts_with(kOgrPrefix) ||
         SourceHasExtension(spec, kOgrExtensions);
}

SpecParts SplitOgrDatasetSpec(std::string_view spec) {
  return SplitSpec(spec, kOgrPrefix);
}

StatusOr<OgrDatasetSpec> ParseOgrDatasetSpec(std::string_view spec) {
  OgrDatasetSpec parsed;
  const auto error = [spec](const std::string& what) {
    return SpecError(spec, what);
  };
  const SpecParts parts = SplitOgrDatasetSpec(spec);
  parsed.source = std::string(parts.source);
  if (parsed.source.empty()) return error("no source before the options");
  if (parts.options.empty()) return parsed;

  std::vector<SpecOption> options;
  RETURN_IF_ERROR(ParseSpecOptions(spec, &options));
  for (SpecOption& option : options) {
    const std::string& name = option.name;
    std::string& value = option.value;
    if (name == "oo") {
      if (value.find('=') == std::string::npos) {
        return error("open option " + QuotedInput(value) +
                     " is not NAME=VALUE");
      }
      parsed.open_options.push_back(std::move(value));
      continue;
    }
    std::string* field = nullptr;
    if (name == "layer") field = &parsed.layer;
    if (name == "z") field = &parsed.z_field;
    if (name == "where") field = &parsed.where;
    if (name == "breaklines") field = &parsed.breaklines_layer;
    if (name == "domain") field = &parsed.domain_layer;
    if (name == "a_srs") field = &parsed.assigned_crs;
    if (name == "driver") field = &parsed.driver;
    if (field == nullptr) {
      return UnknownSpecOption(
          spec, name, "layer, z, where, breaklines, domain, a_srs, oo, driver");
    }
    if (!field->empty()) {
      return error("option " + QuotedInput(name) + " given twice");
    }
    if (value.empty())
      return error("option " + QuotedInput(name) + " is empty");
    *field = std::move(value);
  }
  return parsed;
}

}  // namespace locator::gis
