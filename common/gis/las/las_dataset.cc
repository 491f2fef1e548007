#include "common/gis/las/las_dataset.h"

#include <array>
#include <memory>
#include <utility>

#include "common/gis/dataset_spec_options.h"
#include "common/gis/las/las_crs.h"
#include "common/gis/las/las_header.h"
#include "common/gis/las/las_input.h"

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
  LasHeader header;
  if (Status s = ParseLasHeader(input, &header); !s.ok()) return s;
  Dataset dataset;
  if (Status s = ReadLasCrs(header, input, &dataset.crs); !s.ok()) return s;
  if (Status s = ReadLasPoints(header, input, filter, limits.max_points,
                               &dataset, counts);
      !s.ok()) {
    return s;
  }
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
  LasDatasetSpec parsed;
  if (Status s = ParseLasDatasetSpec(spec, &parsed); !s.ok()) return s;
  if (SourceHasExtension(parsed.path, kLazExtension)) {
    return Status::FailedPrecondition(LazMessage(parsed.path));
  }
  std::unique_ptr<LasInput> input;
  if (Status s = OpenLasFile(parsed.path, &input); !s.ok()) return s;
  LasPointCounts local;
  Dataset dataset;
  if (Status s = Load(*input, parsed.filter, limits, &dataset,
                      counts != nullptr ? counts : &local);
      !s.ok()) {
    return s;
  }
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
