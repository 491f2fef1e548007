// LoadServedDataset: the one place locatord turns a --dataset spec (or a
// Reload request's spec) into a Dataset, at startup and on every reload.
//
// OGR specs (locator::gis::IsOgrDatasetSpec: a GIS file extension or the
// "ogr:" prefix) are read through locator_gis (GDAL), and their CRS is
// checked with PROJ; every other spec goes to the core's LoadDataset (text
// files and generators, no CRS).
//
// Thread-safety: a free function; may run on any thread.

#ifndef LOCATOR_SERVER_DATASET_SOURCE_H_
#define LOCATOR_SERVER_DATASET_SOURCE_H_

#include <string>

#include "common/status.h"
#include "server/core/dataset.h"

namespace locator {

// Loads the dataset `spec` names into *out. Errors are the loaders' (they
// name the file and line, or the source, layer and feature), or
// InvalidArgument when PROJ does not understand the source's CRS.
Status LoadServedDataset(const std::string& spec, const DatasetLimits& limits,
                         Dataset* out);

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASET_SOURCE_H_
