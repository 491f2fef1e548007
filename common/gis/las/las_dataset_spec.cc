#include "common/gis/las/las_dataset_spec.h"

#include <algorithm>
#include <array>
#include <vector>

#include "common/status_macros.h"

namespace locator::gis::las {
namespace {

constexpr std::string_view kLasPrefix = "las:";
constexpr std::array<std::string_view, 2> kLasExtensions = {".las", ".laz"};
constexpr uint64_t kMaxClass = 255;

Status ParseClasses(std::string_view spec, const SpecOption& option,
                    LasFilter* filter) {
  filter->classes.reset();
  std::string_view list = option.value;
  while (true) {
    const size_t comma = list.find(',');
    SpecOption one = option;
    one.value = std::string(list.substr(0, comma));
    uint64_t value = 0;
    if (!SpecOptionInteger(spec, one, 0, kMaxClass, &value).ok()) {
      return BadSpecOption(spec, option.name, option.value,
                           "a comma-separated list of classes 0-255 "
                           "(e.g. 2,9)");
    }
    filter->classes.set(value);
    filter->highest_class =
        std::max(filter->highest_class, static_cast<int>(value));
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  return Status::OK();
}

Status ParseReturns(std::string_view spec, const SpecOption& option,
                    LasFilter* filter) {
  if (option.value == "all") {
    filter->returns = LasReturns::kAll;
  } else if (option.value == "first") {
    filter->returns = LasReturns::kFirst;
  } else if (option.value == "last") {
    filter->returns = LasReturns::kLast;
  } else {
    return BadSpecOption(spec, option.name, option.value, "all, first or last");
  }
  return Status::OK();
}

}  // namespace

bool IsLasDatasetSpec(std::string_view spec) {
  return spec.starts_with(kLasPrefix) ||
         SourceHasExtension(spec, kLasExtensions);
}

SpecParts SplitLasDatasetSpec(std::string_view spec) {
  return SplitSpec(spec, kLasPrefix);
}

StatusOr<LasDatasetSpec> ParseLasDatasetSpec(std::string_view spec) {
  LasDatasetSpec parsed;
  parsed.path = std::string(SplitSpec(spec, kLasPrefix).source);
  if (parsed.path.empty()) {
    return SpecError(spec, "no path before the options");
  }
  std::vector<SpecOption> options;
  RETURN_IF_ERROR(ParseSpecOptions(spec, &options));
  bool have_classes = false;
  bool have_returns = false;
  for (const SpecOption& option : options) {
    bool* seen = option.name == "classes"   ? &have_classes
                 : option.name == "returns" ? &have_returns
                                            : nullptr;
    if (seen == nullptr) {
      return UnknownSpecOption(spec, option.name, "classes, returns");
    }
    if (*seen) {
      return SpecError(spec, "option '" + option.name + "' given twice");
    }
    *seen = true;
    RETURN_IF_ERROR(option.name == "classes"
                        ? ParseClasses(spec, option, &parsed.filter)
                        : ParseReturns(spec, option, &parsed.filter));
  }
  return parsed;
}

}  // namespace locator::gis::las
