// PointStream: a plain point set (points and, optionally, a value each)
// read in chunks from its start, as many times as a build needs, so that
// the tile-set build holds a chunk at a time rather than the dataset.
//
// Thread-safety: one thread at a time.

#ifndef LOCATOR_CORE_TILESET_POINT_STREAM_H_
#define LOCATOR_CORE_TILESET_POINT_STREAM_H_

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "locator/dataset.h"
#include "locator/dataset_sources.h"
#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

class PointStream {
 public:
  virtual ~PointStream() = default;

  // Whether every point comes with a value.
  virtual bool has_values() const = 0;
  // Restarts at the first point.
  [[nodiscard]] virtual Status Rewind() = 0;
  // Replaces *points (and *values, when has_values()) with the next points,
  // at most `max_points` of them; none at the end of the stream.
  [[nodiscard]] virtual Status Read(size_t max_points,
                                    std::vector<Point2>* points,
                                    std::vector<double>* values) = 0;
};

// The points of a generator spec, generated as they are read (never held).
std::unique_ptr<PointStream> GeneratedPointStream(const GeneratorSpec& spec);

// The points of a dataset loaded whole (files, GIS sources). Precondition:
// a plain point set (no constraints).
std::unique_ptr<PointStream> DatasetPointStream(Dataset dataset);

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_POINT_STREAM_H_
