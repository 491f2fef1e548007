#include "server/app/proto_convert.h"

#include <limits>
#include <string>

#include "common/gis/crs_info.h"
#include "common/input_text.h"

namespace locator {
namespace {

v1::LocationType ToProtoLocationType(LocationType type) {
  switch (type) {
    case LocationType::kFace:
      return v1::LOCATION_TYPE_FACE;
    case LocationType::kEdge:
      return v1::LOCATION_TYPE_EDGE;
    case LocationType::kVertex:
      return v1::LOCATION_TYPE_VERTEX;
    case LocationType::kOutsideConvexHull:
      return v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL;
    case LocationType::kOutsideDomain:
      return v1::LOCATION_TYPE_OUTSIDE_DOMAIN;
  }
  return v1::LOCATION_TYPE_UNSPECIFIED;
}

// Whether the answer has a triangle with barycentrics: inside the hull and
// the domain.
bool HasTriangle(const LocateResult& result) {
  return result.type != LocationType::kOutsideConvexHull &&
         result.type != LocationType::kOutsideDomain;
}

void ToProtoPoint(const Point2& point, v1::Point* out) {
  out->set_x(point.x);
  out->set_y(point.y);
}

void ToProtoBox(const BoundingBox& box, v1::BoundingBox* out) {
  out->set_min_x(box.min_x);
  out->set_min_y(box.min_y);
  out->set_max_x(box.max_x);
  out->set_max_y(box.max_y);
}

// Packed columns are sized once and then written through raw pointers, so
// filling a batch allocates nothing per point.
template <typename T>
T* ResizedColumn(google::protobuf::RepeatedField<T>* column, size_t size) {
  column->Resize(static_cast<int>(size), T());
  return column->mutable_data();
}

// The WKT always; name, EPSG code and units as PROJ describes them (the
// loader checked that it can).
void ToCrsStats(const std::string& wkt, v1::CrsStats* crs) {
  crs->set_wkt(wkt);
  const StatusOr<gis::CrsInfo> info = gis::DescribeCrsMemoized(wkt);
  if (!info.ok()) return;
  crs->set_name(info->name);
  crs->set_epsg_code(info->epsg_code);
  for (const std::string& unit : info->axis_units) crs->add_axis_units(unit);
}

void ToDatasetStats(const DatasetInfo& info, v1::DatasetStats* dataset) {
  dataset->set_source(info.source);
  dataset->set_input_points(info.input_points);
  dataset->set_vertices(info.vertices);
  dataset->set_duplicates_merged(info.duplicates_merged);
  dataset->set_triangles(info.triangles);
  ToProtoBox(info.bounding_box, dataset->mutable_bounding_box());
  dataset->set_has_values(info.has_values);
  dataset->set_build_seconds(info.build_seconds);
  if (!info.crs.empty()) ToCrsStats(info.crs, dataset->mutable_crs());
  dataset->set_constraints(info.constraints);
  dataset->set_holes(info.holes);
  dataset->set_all_triangles(info.all_triangles);
  v1::MeshCacheStats* cache = dataset->mutable_mesh_cache();
  cache->set_path(info.mesh_cache.path);
  cache->set_mapped(info.mesh_cache.mapped);
  cache->set_load_error(info.mesh_cache.load_error);
  cache->set_save_error(info.mesh_cache.save_error);
  if (const auto& s = info.simplification) {
    v1::SimplificationStats* out = dataset->mutable_simplification();
    out->set_source_samples(s->source_samples);
    out->set_unserved_samples(s->unserved_samples);
    out->set_vertices(s->vertices);
    out->set_triangles(s->triangles);
    out->set_max_error(s->max_error);
    out->set_target_error(s->target_error);
    out->set_max_points(s->max_points);
    out->set_build_seconds(s->build_seconds);
  }
}

}  // namespace

StatusOr<Point2> FromLocateRequest(const v1::LocateRequest& request) {
  if (!request.has_point()) return Status::InvalidArgument("point is required");
  return Point2{request.point().x(), request.point().y()};
}

void ToLocateResponse(const LocateResult& result,
                      v1::LocateResponse* response) {
  response->set_type(ToProtoLocationType(result.type));
  response->set_triangle_id(result.triangle_id);
  response->mutable_vertex_ids()->Reserve(3);
  response->mutable_vertices()->Reserve(3);
  for (int corner = 0; corner < 3; ++corner) {
    response->add_vertex_ids(result.vertex_ids[corner]);
    ToProtoPoint(result.vertices[corner], response->add_vertices());
  }
  if (HasTriangle(result)) {
    response->mutable_barycentric()->Add(result.barycentric.begin(),
                                         result.barycentric.end());
  } else if (result.type == LocationType::kOutsideConvexHull) {
    response->mutable_hull_edge_vertex_ids()->Add(result.hull_edge_ids.begin(),
                                                  result.hull_edge_ids.end());
  } else {
    response->mutable_domain_edge_vertex_ids()->Add(
        result.domain_edge_ids.begin(), result.domain_edge_ids.end());
  }
  if (result.has_value) response->set_value(result.value);
  v1::Cost* cost = response->mutable_cost();
  cost->set_faces_visited(result.cost.faces_visited);
  cost->set_comparisons(result.cost.comparisons);
  cost->set_table_lookups(result.cost.table_lookups);
  cost->set_total(result.cost.total());
}

BatchAnswerColumns SizeBatchAnswerColumns(const v1::LocateBatchRequest& request,
                                          size_t points,
                                          v1::LocateBatchResponse* response) {
  BatchAnswerColumns columns;
  columns.types = ResizedColumn(response->mutable_types(), points);
  columns.triangle_ids =
      ResizedColumn(response->mutable_triangle_ids(), points);
  columns.costs = ResizedColumn(response->mutable_costs(), points);
  if (request.include_vertex_ids()) {
    columns.vertex_ids =
        ResizedColumn(response->mutable_vertex_ids(), 3 * points);
  }
  if (request.include_barycentric()) {
    columns.barycentric =
        ResizedColumn(response->mutable_barycentric(), 3 * points);
  }
  if (request.include_values()) {
    columns.values = ResizedColumn(response->mutable_values(), points);
  }
  return columns;
}

uint64_t WriteBatchAnswers(std::span<const LocateResult> results, size_t offset,
                           const BatchAnswerColumns& columns) {
  constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
  uint64_t cost_sum = 0;
  for (size_t i = 0; i < results.size(); ++i) {
    const LocateResult& result = results[i];
    const size_t row = offset + i;
    const uint32_t cost = result.cost.total();
    columns.types[row] = ToProtoLocationType(result.type);
    columns.triangle_ids[row] = result.triangle_id;
    columns.costs[row] = cost;
    cost_sum += cost;
    const bool inside = HasTriangle(result);
    for (int corner = 0; corner < 3; ++corner) {
      if (columns.vertex_ids != nullptr) {
        columns.vertex_ids[3 * row + corner] = result.vertex_ids[corner];
      }
      if (columns.barycentric != nullptr) {
        columns.barycentric[3 * row + corner] =
            inside ? result.barycentric[corner] : 0.0;
      }
    }
    if (columns.values != nullptr) {
      columns.values[row] = result.has_value ? result.value : kNoValue;
    }
  }
  return cost_sum;
}

void ToTuningStats(const TuningSummary& summary, bool include_histogram,
                   v1::TuningStats* tuning) {
  tuning->set_snapshot_version(summary.snapshot_version);
  tuning->set_retune_count(summary.retune_count);
  tuning->set_grid_size(static_cast<uint32_t>(summary.grid_size));
  // A strategy without a histogram has no grid box either (it would be the
  // empty box, all infinities).
  if (summary.grid_size > 0)
    ToProtoBox(summary.grid_box, tuning->mutable_grid_box());
  if (include_histogram) {
    tuning->mutable_histogram()->Add(summary.histogram.begin(),
                                     summary.histogram.end());
  }
  for (const BoundingBox& region : summary.hot_regions) {
    ToProtoBox(region, tuning->add_hot_regions());
  }
  tuning->mutable_start_points()->Reserve(
      static_cast<int>(summary.start_points.size()));
  for (const Point2& start : summary.start_points) {
    ToProtoPoint(start, tuning->add_start_points());
  }
  tuning->set_start_point_count(summary.start_point_count);
  tuning->set_hot_queries(summary.hot_queries);
  tuning->set_fallback_queries(summary.fallback_queries);
  const PersistenceSummary& persistence = summary.persistence;
  v1::TuningPersistence* out = tuning->mutable_persistence();
  out->set_state_path(persistence.state_path);
  out->set_restored_from_state(persistence.restored_from_state);
  out->set_load_error(persistence.load_error);
  out->set_saves(persistence.saves);
  out->set_save_error(persistence.save_error);
}

void ToGetStatsResponse(const EngineStats& stats,
                        v1::GetStatsResponse* response) {
  const DatasetInfo& info = stats.dataset;
  ToDatasetStats(info, response->mutable_dataset());
  response->set_strategy(stats.strategy);
  response->set_queries_served(stats.queries);
  response->set_mean_cost_lifetime(stats.mean_cost_lifetime);
  response->set_mean_cost_recent(stats.mean_cost_recent);
  response->set_recent_window(Engine::kStatsWindow);
  response->set_total_cost(stats.total_cost);
  v1::WalkFacesHistogram* walk_faces = response->mutable_walk_faces();
  walk_faces->mutable_upper_bounds()->Add(stats.walk_costs.upper_bounds.begin(),
                                          stats.walk_costs.upper_bounds.end());
  walk_faces->mutable_counts()->Add(stats.walk_costs.counts.begin(),
                                    stats.walk_costs.counts.end());
  walk_faces->set_faces_sum(stats.walk_costs.faces_sum);
  ToTuningStats(stats.tuning, /*include_histogram=*/true,
                response->mutable_tuning());

  v1::MemoryStats* memory = response->mutable_memory();
  memory->set_triangulation_bytes(info.triangulation_bytes);
  memory->set_tuning_bytes(stats.tuning.memory_bytes);
}

StatusOr<std::string> FromReloadRequest(const v1::ReloadRequest& request) {
  // The one reader of the deprecated field.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  const std::string& legacy = request.dataset();
#pragma GCC diagnostic pop
  if (!request.spec().empty() && !legacy.empty() && legacy != request.spec()) {
    return Status::InvalidArgument(
        "spec " + QuotedInput(request.spec()) + " and the deprecated dataset " +
        QuotedInput(legacy) + " differ; send the spec in spec alone");
  }
  return request.spec().empty() ? legacy : request.spec();
}

void ToReloadResponse(const EngineStats& stats, uint64_t generation,
                      v1::ReloadResponse* response) {
  ToDatasetStats(stats.dataset, response->mutable_dataset());
  response->set_generation(generation);
  ToTuningStats(stats.tuning, /*include_histogram=*/false,
                response->mutable_tuning());
}

void ToDatasetEntry(const EngineStats& stats, uint64_t generation,
                    v1::DatasetEntry* entry) {
  ToDatasetStats(stats.dataset, entry->mutable_stats());
  entry->set_strategy(stats.strategy);
  entry->set_generation(generation);
}

void ToGetTopologyResponse(const std::string& name, const std::string& crs,
                           const ShardTiles* tiles,
                           v1::GetTopologyResponse* response) {
  response->set_dataset(name);
  response->set_crs(crs);
  v1::TopologyShard* self = response->add_shards();
  response->set_complete(tiles == nullptr || tiles->serves_all());
  if (tiles == nullptr) return;
  const TileRouter& router = tiles->router();
  response->set_tiled(true);
  v1::BoundingBox* bounds = response->mutable_bounds();
  bounds->set_min_x(router.box().min_x);
  bounds->set_min_y(router.box().min_y);
  bounds->set_max_x(router.box().max_x);
  bounds->set_max_y(router.box().max_y);
  response->set_grid_level(static_cast<uint32_t>(router.level()));
  response->set_fingerprint(tiles->fingerprint());
  for (size_t t = 0; t < router.num_tiles(); ++t) {
    v1::TopologyTile* tile = response->add_tiles();
    tile->set_first_cell(router.first_cell(t));
    tile->set_end_cell(static_cast<uint32_t>(router.end_cell(t)));
  }
  for (const uint32_t t : tiles->served()) self->add_tiles(t);
}

}  // namespace locator
