// QuerySource: the query points of a load run.
//
// A spec is either a workload name of common/workload.h ("uniform",
// "1-cluster", "3-cluster", "d-cluster", "x-cluster", "mixed", "drift"),
// generated into the dataset's bounding box, or "file:PATH", which replays
// the points of PATH (client/points_reader.h format) in order, from the top
// again when they run out.
//
// Owns the generator or the replayed points. Thread-safety: thread-safe
// (calls start on many gRPC threads); one lock per call, not per point.

#ifndef LOCATOR_CLIENT_LOAD_QUERY_SOURCE_H_
#define LOCATOR_CLIENT_LOAD_QUERY_SOURCE_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/mutex.h"
#include "common/workload.h"
#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

class QuerySource {
 public:
  // Whether `spec` names a replay file rather than a generated workload.
  static bool IsReplay(std::string_view spec);
  // Checks `spec` without reading any file: a known workload or "file:"
  // with a path. InvalidArgument otherwise.
  static Status Validate(std::string_view spec);

  // The source for `spec`; `box` places a generated workload and `seed`
  // fixes its stream. NotFound / InvalidArgument for a bad replay file.
  static Status Create(std::string_view spec, const BoundingBox& box,
                       uint64_t seed, std::unique_ptr<QuerySource>* source);

  // The next query.
  Point2 Next() EXCLUDES(mutex_);
  // Fills xs[i], ys[i] with the next xs.size() queries (ys as long as xs).
  void Next(std::span<double> xs, std::span<double> ys) EXCLUDES(mutex_);

 private:
  explicit QuerySource(Workload workload);
  explicit QuerySource(std::vector<Point2> replay);

  Point2 NextLocked() REQUIRES(mutex_);

  Mutex mutex_;
  // Generated, or else...
  std::optional<Workload> workload_ GUARDED_BY(mutex_);
  const std::vector<Point2> replay_;  // ...replayed from a file
  size_t replay_next_ GUARDED_BY(mutex_) = 0;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_QUERY_SOURCE_H_
