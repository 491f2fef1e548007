// Splitting a LocateBatch by shard and merging the shards' answers back
// into input order: what the clients that route (the CLI, locator-load,
// the C++ client library) and the router (locatord --route) do with a
// batch. The parts keep every field of the request but the points; the
// merged answer is the one the whole mesh would give, since every shard of
// a tile set answers as the whole mesh does.
//
// Thread-safety: plain values and pure functions.

#ifndef LOCATOR_COMMON_ROUTING_BATCH_SPLIT_H_
#define LOCATOR_COMMON_ROUTING_BATCH_SPLIT_H_

#include <cstdint>
#include <span>
#include <vector>

#include "common/routing/shard_map.h"
#include "locator/status.h"
#include "locator/v1/locator.pb.h"

namespace locator {

struct BatchSplit {
  // parts[s] goes to shard s; a shard without points has none (and need
  // not be called).
  std::vector<v1::LocateBatchRequest> parts;
  // positions[s][j]: the index in the whole batch of parts[s]'s point j.
  std::vector<std::vector<uint32_t>> positions;
};

// Splits `request` by `map` into *split. A request with a crs is routed by
// `where`, its points transformed to the dataset's CRS (map.crs()), one per
// point, and its parts keep the points as they came. InvalidArgument when
// xs and ys differ in length or a request with a crs comes without
// `where`; FailedPrecondition (NoShardFor) for the first point whose tile
// has no shard.
[[nodiscard]] Status SplitBatch(const v1::LocateBatchRequest& request,
                                const ShardMap& map, BatchSplit* split,
                                std::span<const Point2> where = {});

// Merges `answers` (answers[s] to split.parts[s]; ignored for a part
// without points) into *merged, in input order. Unavailable naming the
// shard when an answer's columns do not match its part (a shard answered
// for other points: it cannot happen but by a bug or a mixed deployment).
[[nodiscard]] Status MergeBatch(
    const v1::LocateBatchRequest& request, const BatchSplit& split,
    std::span<const v1::LocateBatchResponse> answers,
    v1::LocateBatchResponse* merged);

}  // namespace locator

#endif  // LOCATOR_COMMON_ROUTING_BATCH_SPLIT_H_
