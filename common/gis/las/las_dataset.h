// LoadLasDataset: a core Dataset from an uncompressed LAS 1.0-1.4 point
// cloud: the points the spec's filter keeps (LasDatasetSpec), z as their
// value, and the file's CRS (ReadLasCrs). No LAS library is needed: the
// header is checked strictly (ParseLasHeader) and the records are streamed.
//
// Errors start with the path: NotFound for a missing file; FailedPrecondition
// for a compressed (.laz) file, saying how to decompress it; InvalidArgument
// for a bad spec, a malformed file (see las_header.h, las_crs.h) or a file
// of which no point passes the filter (naming the classes it has);
// ResourceExhausted past DatasetLimits::max_points kept points.
//
// Thread-safety: may run on several threads at once.

#ifndef LOCATOR_COMMON_GIS_LAS_LAS_DATASET_H_
#define LOCATOR_COMMON_GIS_LAS_LAS_DATASET_H_

#include <string>

#include "common/gis/las/las_points.h"
#include "locator/dataset.h"
#include "locator/status.h"

namespace locator::gis::las {

// Loads the LAS file `spec` names (see IsLasDatasetSpec) into *out;
// out->source is `spec`. *counts (optional) says what was read and kept.
Status LoadLasDataset(const std::string& spec, Dataset* out,
                      const DatasetLimits& limits = DatasetLimits(),
                      LasPointCounts* counts = nullptr);

// LoadLasDataset on the bytes of a file named `name`, with `filter`: what
// the fuzzer drives.
Status LoadLasBytes(std::string_view bytes, const std::string& name,
                    const LasFilter& filter, const DatasetLimits& limits,
                    Dataset* out, LasPointCounts* counts);

}  // namespace locator::gis::las

#endif  // LOCATOR_COMMON_GIS_LAS_LAS_DATASET_H_
