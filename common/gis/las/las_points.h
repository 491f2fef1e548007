// ReadLasPoints: streams the point records of a LAS file whose header was
// checked (ParseLasHeader) through a LasFilter into a Dataset: each kept
// point's scaled x and y, and its scaled z as the value.
//
// The records are read in chunks of about a megabyte, so memory is the kept
// points (24 bytes each) and one chunk, whatever the file's size.
//
// Thread-safety: a free function; the input is used by the calling thread.

#ifndef LOCATOR_COMMON_GIS_LAS_LAS_POINTS_H_
#define LOCATOR_COMMON_GIS_LAS_LAS_POINTS_H_

#include <array>
#include <cstddef>
#include <cstdint>

#include "common/gis/las/las_dataset_spec.h"
#include "common/gis/las/las_header.h"
#include "common/gis/las/las_input.h"
#include "locator/dataset.h"
#include "locator/status.h"

namespace locator::gis::las {

// What a read saw, for messages and logs.
struct LasPointCounts {
  uint64_t records = 0;   // point records read
  uint64_t kept = 0;      // points that passed the filter
  uint64_t withheld = 0;  // dropped for the withheld flag
  // Records per class (withheld ones included).
  std::array<uint64_t, 256> per_class = {};
};

// Reads every point record of `input` (described by `header`), appending
// the points `filter` keeps to out->points and their z to out->values.
// InvalidArgument if the filter names a class above 31 and the point format
// holds 5-bit classes; ResourceExhausted, before allocating for it, when
// more than `max_points` points pass; IOError as the input's reads.
Status ReadLasPoints(const LasHeader& header, LasInput& input,
                     const LasFilter& filter, size_t max_points, Dataset* out,
                     LasPointCounts* counts);

}  // namespace locator::gis::las

#endif  // LOCATOR_COMMON_GIS_LAS_LAS_POINTS_H_
