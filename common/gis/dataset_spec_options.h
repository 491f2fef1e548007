// Dataset spec options: the "?NAME=VALUE&..." suffix that every dataset spec
// may carry, and the two options every kind of dataset takes.
//
// Every spec locatord reads is SOURCE[?OPTIONS], whatever names the source
// (a CSV/XYZ or Triangle file, a generator, an OGR source, a raster, a LAS
// file): the options begin at the spec's FIRST '?'. OPTIONS are NAME=VALUE
// pairs separated by '&' (empty pairs are skipped); values are %-decoded, so
// a literal '&' in a value is %26 and '%' is %25; names and the source are
// taken verbatim. One rule for every kind, so no spec means two things; the
// price is that a file whose own path contains '?' cannot be named directly
// (link or rename it; the loaders say so when such a file exists).
//
// The options every kind takes (the kind's loader never sees them):
//   max_error=E   thin the dataset by greedy insertion until every source
//                 sample lies within E (in the values' units) of the served
//                 surface; E >= 0 and finite; 0 keeps every sample
//   max_points=N  stop inserting at N vertices (N >= 3); whichever of the
//                 two limits is reached first wins
// A raster is always triangulated this way (max_error=0 by default); a point
// dataset only when one of the two is given.
//
// Thread-safety: free functions on plain values.

#ifndef LOCATOR_COMMON_GIS_DATASET_SPEC_OPTIONS_H_
#define LOCATOR_COMMON_GIS_DATASET_SPEC_OPTIONS_H_

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"

namespace locator::gis {

// One option as written and as decoded.
struct SpecOption {
  std::string name;
  std::string value;      // %-decoded
  std::string_view text;  // "NAME=VALUE" as written: a view into the spec
};

// A spec's parts, verbatim: its kind's prefix ("ogr:", "raster:", "las:")
// or "", the source, and "?OPTIONS" or "". prefix + source + options is the
// spec again.
struct SpecParts {
  std::string_view prefix;
  std::string_view source;
  std::string_view options;
};

// Splits `spec` at its first '?', taking `prefix` off its front when it
// starts with it (it does not check the options).
SpecParts SplitSpec(std::string_view spec, std::string_view prefix = {});

// Whether the source of `spec` ends in one of `extensions` (".tif"; lower
// case), ignoring case: "DEM.TIF?band=2" ends in ".tif".
bool SourceHasExtension(std::string_view spec,
                        std::span<const std::string_view> extensions);

// Parses the options of `spec` into *out, in order. InvalidArgument naming
// the spec for an option without '=' or with a malformed %-escape.
Status ParseSpecOptions(std::string_view spec, std::vector<SpecOption>* out);

// InvalidArgument "dataset spec 'SPEC': WHAT", the spec as QuotedInput()
// shows it (a request's spec is echoed, not copied).
Status SpecError(std::string_view spec, std::string_view what);

// The error for option `name` of `spec` with a bad value, saying what
// `expected` ("a finite number >= 0").
Status BadSpecOption(std::string_view spec, std::string_view name,
                     std::string_view value, std::string_view expected);

// The error for an option no kind knows: "unknown option 'x' (known: ...)",
// `known` being the kind's own options; the options every kind takes are
// added to the list.
Status UnknownSpecOption(std::string_view spec, std::string_view name,
                         std::string_view known);

// Parses option `option` of `spec` as a finite double >= `min` / an integer
// in [min, max]; BadSpecOption otherwise.
Status SpecOptionDouble(std::string_view spec, const SpecOption& option,
                        double min, double* out);
Status SpecOptionInteger(std::string_view spec, const SpecOption& option,
                         uint64_t min, uint64_t max, uint64_t* out);

// The options every kind takes (see above).
struct SimplifySpec {
  // Whether max_error or max_points was given.
  bool requested = false;
  double max_error = 0;
  uint64_t max_points = 0;  // 0: no limit
};

// Takes max_error and max_points out of `spec`: *simplify gets them, and
// *rest is `spec` without them (the source, and '?' with the other options
// as written, if any). InvalidArgument naming the spec and the option for a
// malformed option, a value out of range or an option given twice.
Status TakeSimplifyOptions(std::string_view spec, SimplifySpec* simplify,
                           std::string* rest);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_DATASET_SPEC_OPTIONS_H_
