// LasDatasetSpec: a dataset spec that names a LAS point cloud, parsed.
//
// Syntax (dataset_spec_options.h has the option rules and the options every
// kind takes, max_error and max_points):
//   PATH.las[?OPTIONS]   (any case; PATH.laz is recognized to be refused
//                        with how to decompress it)
//   las:PATH[?OPTIONS]   a LAS file by any other name
// OPTIONS, '&'-separated:
//   classes=C[,C...]     keep only points of these classes, 0-255 (0-31 in
//                        point formats 0-5), e.g. classes=2,9 for ground
//                        and water. Default: every class.
//   returns=all|first|last
//                        every return (default); first returns only
//                        (return number 1); last returns only (return
//                        number = number of returns).
// Withheld points (the withheld flag set) are always dropped: the LAS
// specification says they are deleted and not to be processed.
//
// Thread-safety: free functions; a LasDatasetSpec is a plain value.

#ifndef LOCATOR_COMMON_GIS_LAS_LAS_DATASET_SPEC_H_
#define LOCATOR_COMMON_GIS_LAS_LAS_DATASET_SPEC_H_

#include <bitset>
#include <string>
#include <string_view>

#include "common/gis/dataset_spec_options.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis::las {

enum class LasReturns { kAll, kFirst, kLast };

// Which points of a file a dataset keeps.
struct LasFilter {
  // Kept classes, by class number; all by default.
  std::bitset<256> classes = std::bitset<256>().set();
  // The highest class the classes= option names; -1 without the option.
  // Point formats 0-5 hold classes 0-31 only, so asking for a higher one
  // there is an error rather than an empty result.
  int highest_class = -1;
  LasReturns returns = LasReturns::kAll;
};

struct LasDatasetSpec {
  std::string path;
  LasFilter filter;
};

// True when `spec` names a LAS file: the "las:" prefix, or a source ending
// in .las or .laz.
bool IsLasDatasetSpec(std::string_view spec);

// Splits `spec` into its parts, verbatim: "las:" or "", the path, and
// "?OPTIONS" or "".
SpecParts SplitLasDatasetSpec(std::string_view spec);

// Parses `spec`; InvalidArgument naming the spec and the option for an
// unknown or repeated option, a class that is not 0-255, an unknown returns
// value, or no path.
StatusOr<LasDatasetSpec> ParseLasDatasetSpec(std::string_view spec);

}  // namespace locator::gis::las

#endif  // LOCATOR_COMMON_GIS_LAS_LAS_DATASET_SPEC_H_
