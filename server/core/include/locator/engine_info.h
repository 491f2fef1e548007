// What an engine reports about itself (Engine::dataset_info(), Stats(),
// domain_outline()): where its dataset came from, the facts of its mesh,
// how the mesh cache served it, the certificate of a simplified TIN, its
// walk costs and what its strategy has learned. Plain values, carried and
// never interpreted by the engine once made.
//
// Thread-safety: plain values.

#ifndef LOCATOR_ENGINE_INFO_H_
#define LOCATOR_ENGINE_INFO_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "locator/geometry.h"

namespace locator {

// The most segments of Engine::EdgeSample() and of each list of
// Engine::domain_outline().
inline constexpr size_t kEdgeSampleSize = 3000;
inline constexpr size_t kOutlineSize = 3000;

// A dataset's domain drawn as segments (Engine::domain_outline()): for the
// status page and stats, each list thinned to at most kOutlineSize.
struct DomainOutline {
  // Edges between an in-domain triangle and an out-of-domain face or the
  // outside of the hull; empty for a dataset without a domain (rings,
  // .poly segments or mesh triangles).
  std::vector<std::array<Point2, 2>> boundary;
  // Constrained edges that are not boundary edges and lie along a
  // breakline or a .poly segment (a mesh's own edges are constrained too,
  // but are not breaklines).
  std::vector<std::array<Point2, 2>> breaklines;
};

// How the mesh cache served one build.
struct MeshCacheOutcome {
  // The dataset's mesh file; empty without a cache directory.
  std::string path;
  // The dataset's fingerprint (DatasetFingerprint), which names the file.
  uint64_t fingerprint = 0;
  // Whether the mesh was mapped from `path` instead of triangulated.
  bool mapped = false;
  // Why an existing file was not used; empty otherwise.
  std::string load_error;
  // Why writing the file after triangulating failed; empty otherwise.
  std::string save_error;
};

// The certificate that GetStats and ListDatasets report (the proto block
// `simplification`).
struct SimplificationStats {
  // Valid source samples read (pixels that are not nodata, or points).
  uint64_t source_samples = 0;
  // Valid source samples outside the served domain, so without a value and
  // not in max_error: for a grid, samples that are the corner of no cell
  // with four valid corners (a lone pixel, a one-pixel-wide line); for
  // points, points in a hole or outside the domain's boundary.
  uint64_t unserved_samples = 0;
  uint64_t vertices = 0;   // kept
  uint64_t triangles = 0;  // served
  // max |z - TIN(x, y)| over every served source sample, measured on the
  // output TIN with the engine's own linear interpolation (barycentric.h).
  double max_error = 0;
  double target_error = 0;  // TinOptions::max_error
  uint64_t max_points = 0;  // TinOptions::max_points
  double build_seconds = 0;
};

// What an engine reports about its dataset besides the mesh: where it came
// from, its CRS and, for a TIN simplified from source samples, the
// certificate. Carried, never interpreted.
struct DatasetOrigin {
  std::string source;
  // WKT; empty when the dataset has none.
  std::string crs;
  std::optional<SimplificationStats> simplification;
};

struct DatasetInfo {
  std::string source;
  uint64_t input_points = 0;
  uint64_t vertices = 0;           // distinct points
  uint64_t duplicates_merged = 0;  // input_points - vertices
  uint64_t triangles = 0;          // in-domain triangles
  uint64_t all_triangles = 0;      // finite faces, in the domain or not
  uint64_t constraints = 0;        // constrained segments inserted
  uint64_t holes = 0;              // out-of-domain regions inside the hull
  BoundingBox bounding_box;
  bool has_values = false;
  // The dataset's CRS as WKT (Dataset::crs); empty when it has none.
  std::string crs;
  // Bytes of the serving mesh, all the engine keeps of the triangulation
  // (CGAL's is freed once the mesh is built).
  size_t triangulation_bytes = 0;
  // Seconds Create() took, whether it triangulated or mapped the mesh.
  double build_seconds = 0;
  // How EngineOptions::mesh_cache_dir served this build.
  MeshCacheOutcome mesh_cache;
  // For a TIN simplified from its source (a raster, or points given
  // max_error): how, with the measured error. Unset otherwise.
  std::optional<SimplificationStats> simplification;
};

// A snapshot of a WalkCostHistogram.
struct WalkCostCounts {
  // counts[i] is the number of walks with upper_bounds[i - 1] < faces <=
  // upper_bounds[i]; the last count (one more than bounds) is the walks
  // above every bound.
  std::vector<uint32_t> upper_bounds;
  std::vector<uint64_t> counts;
  uint64_t faces_sum = 0;
};

// How a strategy's learned state persists across restarts (self-tuning
// with TuningOptions::state_dir).
struct PersistenceSummary {
  // The state file; empty when nothing persists.
  std::string state_path;
  // Whether the tuning was restored from it when the strategy was built.
  bool restored_from_state = false;
  // Why an existing state file was not used; empty otherwise.
  std::string load_error;
  // State files written so far, and why the last write failed ("" if it
  // did not).
  uint64_t saves = 0;
  std::string save_error;
};

// What a strategy has learned, for GetStats and the status page.
struct TuningSummary {
  // Monotonic version of the published snapshot (0: none published yet).
  uint64_t snapshot_version = 0;
  uint64_t retune_count = 0;
  // The query histogram: grid_size x grid_size cells over grid_box, row-major
  // from (min_x, min_y); counts are decayed for self-tuning. Empty when the
  // strategy keeps none.
  int grid_size = 0;
  BoundingBox grid_box;
  std::vector<double> histogram;
  // Rectangles where queries concentrate.
  std::vector<BoundingBox> hot_regions;
  // A sample of the start points in use (at most a few thousand).
  std::vector<Point2> start_points;
  // Total number of start points in use.
  uint64_t start_point_count = 0;
  // Bytes of the tuning structures (the published snapshot).
  size_t memory_bytes = 0;
  PersistenceSummary persistence;
  // Queries answered since the strategy was created in cells it had tuned
  // for (hot) and elsewhere (fallback). Self-tuning only; 0 for the others.
  uint64_t hot_queries = 0;
  uint64_t fallback_queries = 0;
  // Self-tuning only: wall-clock ns spent re-tuning (inline in queries or on
  // the tuner thread), and the most table-building work (StartTable::Builder
  // units) one located query paid for inline.
  uint64_t tune_nanos = 0;
  uint64_t max_tune_units_per_query = 0;
};

struct EngineStats {
  DatasetInfo dataset;
  std::string strategy;
  uint64_t queries = 0;
  // Sum of the costs of all queries (mean_cost_lifetime * queries, exactly).
  uint64_t total_cost = 0;
  double mean_cost_lifetime = 0;
  // Mean cost over the most recent completed window of kStatsWindow queries
  // (the lifetime mean until the first window completes).
  double mean_cost_recent = 0;
  // Faces visited per located query.
  WalkCostCounts walk_costs;
  TuningSummary tuning;
};

}  // namespace locator

#endif  // LOCATOR_ENGINE_INFO_H_
