#include "common/routing/batch_split.h"

#include <string>

namespace locator {
namespace {

// Copies entries [from * width, (from + 1) * width) of `source` to entries
// [to * width, ...) of `target`.
template <typename Column>
void CopyEntries(const Column& source, int from, Column* target, int to,
                 int width) {
  for (int k = 0; k < width; ++k) {
    target->Set(to * width + k, source.Get(from * width + k));
  }
}

}  // namespace

Status SplitBatch(const v1::LocateBatchRequest& request, const ShardMap& map,
                  BatchSplit* split, std::span<const Point2> where) {
  if (request.xs_size() != request.ys_size()) {
    return Status::InvalidArgument(
        "xs has " + std::to_string(request.xs_size()) + " values and ys " +
        std::to_string(request.ys_size()));
  }
  if (!request.crs().empty() &&
      where.size() != static_cast<size_t>(request.xs_size())) {
    return Status::InvalidArgument(
        "a batch with a crs is routed by its points in the dataset's CRS, "
        "and they were not given; send it to a router (locatord --route) or "
        "transform the points first");
  }
  v1::LocateBatchRequest scope = request;
  scope.clear_xs();
  scope.clear_ys();
  split->parts.assign(map.num_shards(), scope);
  split->positions.assign(map.num_shards(), {});
  for (int i = 0; i < request.xs_size(); ++i) {
    const Point2 p{request.xs(i), request.ys(i)};
    const Point2 at = request.crs().empty() ? p : where[i];
    const uint32_t shard = map.ShardOf(at);
    if (shard == ShardMap::kNoShard) {
      return NoShardFor(map.dataset(), static_cast<size_t>(i), p,
                        map.TileOf(at));
    }
    split->parts[shard].add_xs(p.x);
    split->parts[shard].add_ys(p.y);
    split->positions[shard].push_back(static_cast<uint32_t>(i));
  }
  return Status::OK();
}

Status MergeBatch(const v1::LocateBatchRequest& request,
                  const BatchSplit& split,
                  std::span<const v1::LocateBatchResponse> answers,
                  v1::LocateBatchResponse* merged) {
  const int n = request.xs_size();
  const int vertex_width = request.include_vertex_ids() ? 3 : 0;
  const int barycentric_width = request.include_barycentric() ? 3 : 0;
  const int value_width = request.include_values() ? 1 : 0;
  merged->Clear();
  merged->mutable_types()->Resize(n, 0);
  merged->mutable_triangle_ids()->Resize(n, 0);
  merged->mutable_costs()->Resize(n, 0);
  merged->mutable_vertex_ids()->Resize(n * vertex_width, 0);
  merged->mutable_barycentric()->Resize(n * barycentric_width, 0);
  merged->mutable_values()->Resize(n * value_width, 0);
  uint64_t total_cost = 0;
  for (size_t s = 0; s < split.positions.size(); ++s) {
    const std::vector<uint32_t>& positions = split.positions[s];
    if (positions.empty()) continue;
    const v1::LocateBatchResponse& answer = answers[s];
    const int m = static_cast<int>(positions.size());
    if (answer.types_size() != m || answer.triangle_ids_size() != m ||
        answer.costs_size() != m ||
        answer.vertex_ids_size() != m * vertex_width ||
        answer.barycentric_size() != m * barycentric_width ||
        answer.values_size() != m * value_width) {
      return Status::Unavailable("shard " + std::to_string(s) + " answered " +
                                 std::to_string(answer.types_size()) +
                                 " points (or other columns) for " +
                                 std::to_string(m));
    }
    for (int j = 0; j < m; ++j) {
      const int i = static_cast<int>(positions[j]);
      merged->set_types(i, answer.types(j));
      merged->set_triangle_ids(i, answer.triangle_ids(j));
      merged->set_costs(i, answer.costs(j));
      CopyEntries(answer.vertex_ids(), j, merged->mutable_vertex_ids(), i,
                  vertex_width);
      CopyEntries(answer.barycentric(), j, merged->mutable_barycentric(), i,
                  barycentric_width);
      CopyEntries(answer.values(), j, merged->mutable_values(), i, value_width);
    }
    total_cost += answer.total_cost();
  }
  merged->set_total_cost(total_cost);
  return Status::OK();
}

}  // namespace locator
