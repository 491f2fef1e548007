#include "common/gis/las/las_dataset.h"

#include <array>
#include <memory>
#include <utility>

#include "common/gis/dataset_spec_options.h"
#include "common/gis/las/las_crs.h"
#include "common/gis/las/las_header.h"
#include "common/gis/las/las_input.h"
#include "common/status_macros.h"

namespace locator::gis::las {
namespace {

constexpr std::array<std::string_view, 1> kLazExtension = {".laz"};
// Classes an empty-result message lists at most.
constexpr int kListedClasses = 8;

// "class 1 (1200 points), class 2 (340 points)": the classes the file has.
std::string ClassesPresent(const LasPointCounts& counts) {
  std::string text;
  int listed = 0;
  for (size_t c = 0; c < counts.per_class.size(); ++c) {
    if (counts.per_class[c] == 0) continue;
    if (listed++ == kListedClasses) return text + ", ...";
    if (!text.empty()) text += ", ";
    text += "class " + std::to_string(c) + " (" +
            std::to_string(counts.per_class[c]) + " points)";
  }
  return text;
}

Status Load(LasInput& input, const LasFilter& filter,
            const DatasetLimits& limits, Dataset* out, LasPointCounts* counts) {
  ASSIGN_OR_RETURN(const LasHeader header, ParseLasHeader(input));
  Dataset dataset;
  ASSIGN_OR_RETURN(dataset.crs, ReadLasCrs(header, input));
  RETURN_IF_ERROR(ReadLasPoints(header, input, filter, limits.max_points,
                                &dataset, counts));
  if (counts->records == 0) {
    return Status::InvalidArgument(input.name() + ": no point records");
  }
  if (counts->kept == 0) {
    return Status::InvalidArgument(
        input.name() + ": none of its " + std::to_string(counts->records) +
        " points passes the filters (" + std::to_string(counts->withheld) +
        " withheld; it has " + ClassesPresent(*counts) + ")");
  }
  *out = std::move(dataset);
  return Status::OK();
}

}  // namespace

Status LoadLasDataset(const std::string& spec, Dataset* out,
                      const DatasetLimits& limits, LasPointCounts* counts) {
  ASSIGN_OR_RETURN(const LasDatasetSpec parsed, ParseLasDatasetSpec(spec));
  if (SourceHasExtension(parsed.path, kLazExtension)) {
    return Status::FailedPrecondition(LazMessage(parsed.path));
  }
  ASSIGN_OR_RETURN(const std::unique_ptr<LasInput> input,
                   OpenLasFile(parsed.path));
  LasPointCounts local;
  Dataset dataset;
  RETURN_IF_ERROR(Load(*input, parsed.filter, limits, &dataset,
                       counts != nullptr ? counts : &local));
  dataset.source = spec;
  *out = std::move(dataset);
  return Status::OK();
}

Status LoadLasBytes(std::string_view bytes, const std::string& name,
                    const LasFilter& filter, const DatasetLimits& limits,
                    Dataset* out, LasPointCounts* counts) {
  const std::unique_ptr<LasInput> input = LasMemoryInput(bytes, name);
  return Load(*input, filter, limits, out, counts);
}

}  // namespace locator::gis::las
