#include "server/dataset_source.h"

#include "common/gis/crs_info.h"
#include "common/gis/ogr_dataset.h"
#include "common/gis/ogr_dataset_spec.h"

namespace locator {

Status LoadServedDataset(const std::string& spec, const DatasetLimits& limits,
                         Dataset* out) {
  if (!gis::IsOgrDatasetSpec(spec)) return LoadDataset(spec, out, limits);
  Dataset dataset;
  if (Status status = gis::LoadOgrDataset(spec, &dataset, limits);
      !status.ok()) {
    return status;
  }
  if (!dataset.crs.empty()) {
    // Stats and request transforms rely on PROJ knowing it.
    gis::CrsInfo info;
    if (Status status = gis::DescribeCrsMemoized(dataset.crs, &info);
        !status.ok()) {
      return Status::InvalidArgument(spec + ": " + status.message());
    }
  }
  *out = std::move(dataset);
  return Status::OK();
}

}  // namespace locator
