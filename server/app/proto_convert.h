// Conversions from the core's plain result and statistics types to the
// locator.v1 messages. The service and the no-op server answer through these
// functions only, so both put the same fields on the wire.
//
// Thread-safety: free functions. WriteBatchAnswers may run concurrently on
// disjoint slices of the same columns.

#ifndef LOCATOR_SERVER_PROTO_CONVERT_H_
#define LOCATOR_SERVER_PROTO_CONVERT_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "locator/engine.h"
#include "locator/locate_result.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"
#include "server/core/strategies/point_locator.h"
#include "server/datasets/shard_tiles.h"

namespace locator {

// Sets `*point` to the point of `request`. InvalidArgument "point is
// required" if the request has none: proto3 gives message fields presence,
// and a missing point is not (0, 0).
StatusOr<Point2> FromLocateRequest(const v1::LocateRequest& request);

// Fills `response` with every field of `result`, as locator.proto documents
// them (barycentric empty and hull_edge_vertex_ids set outside the hull; value
// only when the result has one).
void ToLocateResponse(const LocateResult& result, v1::LocateResponse* response);

// The columns of a LocateBatchResponse, sized for a whole batch, as raw
// arrays so that several threads can each fill their own slice.
struct BatchAnswerColumns {
  int* types = nullptr;
  int64_t* triangle_ids = nullptr;
  uint32_t* costs = nullptr;
  // The optional columns are null unless the request asked for them.
  int64_t* vertex_ids = nullptr;
  double* barycentric = nullptr;
  double* values = nullptr;
};

// Sizes `response`'s columns for `points` answers, including the optional
// columns `request` asks for, and returns them.
BatchAnswerColumns SizeBatchAnswerColumns(const v1::LocateBatchRequest& request,
                                          size_t points,
                                          v1::LocateBatchResponse* response);

// Writes `results` as answers [offset, offset + results.size()) of `columns`;
// returns the sum of their costs.
uint64_t WriteBatchAnswers(std::span<const LocateResult> results, size_t offset,
                           const BatchAnswerColumns& columns);

// Fills `tuning` from `summary`; the histogram only if `include_histogram`.
void ToTuningStats(const TuningSummary& summary, bool include_histogram,
                   v1::TuningStats* tuning);

// Fills `response` with everything GetStats reports about the engine (the
// service adds its generation and reload state). The one mapping of
// EngineStats: every output of the statistics (GetStats, /api/stats,
// /metrics) is made from its result.
void ToGetStatsResponse(const EngineStats& stats,
                        v1::GetStatsResponse* response);

// The spec a Reload asks to load: `spec`, or the deprecated `dataset` of
// clients from before `spec` existed. InvalidArgument when both are set and
// differ.
StatusOr<std::string> FromReloadRequest(const v1::ReloadRequest& request);

// Fills `response` for a Reload that made the engine with `stats` serve as
// `generation`.
void ToReloadResponse(const EngineStats& stats, uint64_t generation,
                      v1::ReloadResponse* response);

// Fills the statistics, strategy and generation of a ListDatasets entry for
// the engine with `stats` serving as `generation` (the service adds the
// name and the serving flags).
void ToDatasetEntry(const EngineStats& stats, uint64_t generation,
                    v1::DatasetEntry* entry);

// The topology of dataset `name` in CRS `crs`: the tiles of a tile set and
// those this server serves (`tiles`), or one shard serving all of a dataset
// that is not a tile set (`tiles` null).
void ToGetTopologyResponse(const std::string& name, const std::string& crs,
                           const ShardTiles* tiles,
                           v1::GetTopologyResponse* response);

}  // namespace locator

#endif  // LOCATOR_SERVER_PROTO_CONVERT_H_
