// Engine: a dataset's serving mesh plus the locator strategy answering on
// it, with query validation and serving statistics. This is the one entry
// point the service and tools use; it exposes plain types only (no CGAL).
//
// Owns: the serving mesh (shared with nothing else once Create() returns),
// the strategy, and what Create() derived with the mesh (from CGAL's
// triangulation before freeing it, or from the tiles) or read from the
// mesh file (dataset facts, edge sample, domain outline).
//
// Thread-safety: all const methods and Retune() may be called concurrently.
// Invariant: the mesh is immutable once Create() returns; every query
// (locates, values, profiles, rasters) runs on it alone.

#ifndef LOCATOR_ENGINE_H_
#define LOCATOR_ENGINE_H_

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "locator/dataset.h"
#include "locator/engine_info.h"
#include "locator/geometry.h"
#include "locator/interpolation.h"
#include "locator/locate_result.h"
#include "locator/mesh_patch.h"
#include "locator/profile.h"
#include "locator/raster.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "locator/tuning_options.h"

namespace locator {

class PointLocator;
class ServingMesh;
class WalkCostHistogram;
struct BuiltMesh;

// InvalidArgument naming point `index` of a batch and its coordinates unless
// both are finite: the one wording of that error, wherever a batch is
// checked.
Status CheckBatchPoint(const Point2& q, size_t index);

struct EngineOptions {
  // walk | jump-and-walk | adaptive-paper | self-tuning
  std::string strategy = "self-tuning";
  TuningOptions tuning;
  // A directory of mesh files (mesh_cache.h): Create() maps the dataset's
  // file there instead of triangulating, or writes it after triangulating.
  // Empty: always triangulate, write nothing.
  std::string mesh_cache_dir;
  // Threads that triangulate a dataset without constraints, in tiles
  // (tiling/tiled_build.h); 0: one per hardware thread. The mesh and its
  // ids do not depend on it. Constrained datasets are built on one.
  unsigned build_threads = 0;
};

class Engine {
 public:
  static constexpr uint64_t kStatsWindow = 1000;

  // Triangulates `dataset` (TriangulateMesh: in tiles on
  // options.build_threads threads without constraints, with CGAL with
  // them), derives the serving mesh and sets up the strategy on it; or,
  // with options.mesh_cache_dir, maps the mesh from the dataset's file
  // there (see BuildOrMapMesh). Fails
  // with InvalidArgument for fewer than 3 distinct or all-collinear points,
  // or an unknown strategy.
  static StatusOr<std::unique_ptr<Engine>> Create(Dataset dataset,
                                                  const EngineOptions& options);
  // As Create, for `tin`, a TIN simplified from source samples (its mesh
  // as constraints.triangles, see server/core/terrain/) whose certificate
  // is `simplification`: dataset_info() reports it.
  static StatusOr<std::unique_ptr<Engine>> CreateSimplified(
      Dataset tin, const SimplificationStats& simplification,
      const EngineOptions& options);
  // The engine of the dataset with `fingerprint` from its mesh file in
  // options.mesh_cache_dir, without the dataset itself (see
  // FindGeneratedFingerprint); stats report `origin` as its source, CRS and
  // certificate. NotFound if there is no file, or why the file is unusable
  // (MapCachedMesh); the outcome is in dataset_info().mesh_cache either way
  // when it succeeds.
  static StatusOr<std::unique_ptr<Engine>> CreateFromMeshFile(
      uint64_t fingerprint, DatasetOrigin origin, const EngineOptions& options);
  ~Engine();

  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  // Locates one point, its value interpolated `how`. InvalidArgument if a
  // coordinate is NaN or infinite, or as CheckInterpolation(how).
  Status Locate(const Point2& q, LocateResult* result,
                Interpolation how = Interpolation::kLinear) const;

  // Locates every point of `queries` into `results` (resized), in input
  // order. Validates all points first: the first non-finite one fails the
  // whole call with InvalidArgument naming its index, and nothing is located.
  // `keep_going`, if set, is polled between chunks; returning false stops the
  // batch with Unavailable("cancelled").
  // Values are interpolated `how` (InvalidArgument as CheckInterpolation);
  // with Detail::kLocation no barycentric or value is computed. Points are
  // located along a Hilbert curve, each walk starting near the previous
  // answer; at most 2^32 - 1 points.
  Status LocateBatch(std::span<const Point2> queries,
                     std::vector<LocateResult>* results,
                     const std::function<bool()>& keep_going = nullptr,
                     Interpolation how = Interpolation::kLinear,
                     Detail detail = Detail::kFull) const;

  // OK if this dataset's values can be interpolated `how`; InvalidArgument
  // saying why not (natural neighbour needs a dataset without constraints).
  Status CheckInterpolation(Interpolation how) const;

  // The surface along `line` (see profile.h): its exact breakpoints,
  // options.samples evenly spaced samples and the gaps outside the hull or
  // the domain. The walk to line[0] starts where the strategy would start a
  // locate of it. InvalidArgument for fewer than 2 points, a non-finite one,
  // a line longer than the largest double or an interpolation the dataset
  // refuses; ResourceExhausted when the line would enter more than
  // options.max_faces triangles (see TraceProfile in profile_trace.h).
  Status TraceProfile(std::span<const Point2> line,
                      const ProfileOptions& options, Profile* out) const;

  // Renders rows [first_row, first_row + rows) of `spec` (see raster.h)
  // into `out`, row by row. InvalidArgument if CheckRasterSpec(spec) or
  // CheckInterpolation fails or the rows are not within spec.height.
  // Threads may render disjoint rows at once.
  Status RenderRows(const RasterSpec& spec, uint32_t first_row, uint32_t rows,
                    double* out) const;

  // Renders the value at each of `points` into `out` (points.size()
  // values) with RenderRows' scan coherence, for points in rows of
  // `row_length` in scan order that are not a raster of this dataset's CRS
  // (a map tile's pixel centres mapped here): each walk starts from the
  // previous point's triangle, each row's first from the previous row's
  // first. A non-finite point, or one outside the hull or the domain, gets
  // `nodata`. InvalidArgument as CheckInterpolation(how), or if row_length
  // is 0.
  Status RenderPoints(std::span<const Point2> points, size_t row_length,
                      Interpolation how, double nodata, double* out) const;

  // Renders the gradient of the TIN's facet at each of `points` into `out`
  // (points.size() gradients), walking as RenderPoints does: the exact
  // slope of the triangle's plane, which is what shading wants. A point on
  // an edge or a vertex takes one of the in-domain faces that meet there; a
  // non-finite point, one outside the hull or the domain, and every point
  // of a dataset without values get NaN. InvalidArgument if row_length is 0.
  Status RenderGradients(std::span<const Point2> points, size_t row_length,
                         FacetGradient* out) const;

  // The in-domain triangles whose bounding boxes meet `box` (this
  // dataset's CRS), with their corners' positions, values and public ids,
  // into `out`. FailedPrecondition without values; InvalidArgument for a
  // box that is not finite; ResourceExhausted naming the limit when they
  // have more than `max_vertices` corners.
  Status MeshInBox(const BoundingBox& box, size_t max_vertices,
                   MeshPatch* out) const;

  // Re-tunes the strategy now (no-op for fixed strategies).
  void Retune();

  // Saves the strategy's learned state to its state file now if it changed
  // since the last save (EngineOptions::tuning.state_dir); OK when nothing
  // persists. Safe while queries and re-tunes run.
  Status SaveTuningState();

  const DatasetInfo& dataset_info() const { return info_; }
  EngineStats Stats() const;

  // At most kEdgeSampleSize edges of the triangulation, spread evenly over
  // its edge list, each as its two endpoints: enough to draw the mesh's
  // outline and density. Computed once, by Create().
  const std::vector<std::array<Point2, 2>>& EdgeSample() const {
    return edge_sample_;
  }

  // The domain's boundary and the breaklines, at most kOutlineSize edges
  // each (see OutlineOf); both empty for a plain point cloud. Computed once,
  // by Create().
  const DomainOutline& domain_outline() const { return outline_; }

 private:
  // Tests watch the strategy through it (tests/core/engine_test_peer.h).
  friend class EngineTestPeer;

  Engine();
  // Create with the certificate `simplification`, if any.
  static StatusOr<std::unique_ptr<Engine>> Build(
      Dataset dataset, std::optional<SimplificationStats> simplification,
      const EngineOptions& options);
  // Sets up the strategy of `e` on `built` and fills the dataset facts;
  // `start` is when the build began.
  static StatusOr<std::unique_ptr<Engine>> Finish(
      BuiltMesh built, const EngineOptions& options,
      std::chrono::steady_clock::time_point start, std::unique_ptr<Engine> e);
  // Counts `queries` answered at total `cost` in the serving statistics.
  void Record(uint64_t queries, uint64_t cost) const;
  // What the strategy is asked to fill for a locate of `detail` whose
  // values are interpolated `how`: the value only when it is linear (the
  // strategy's own), so that each value is computed once.
  static Detail StrategyDetail(Interpolation how, Detail detail);
  // Fills the values of `results`, located with Detail::kAllButValue, as
  // interpolated `how` in the face the strategy found.
  void InterpolateValues(std::span<const Point2> queries, Interpolation how,
                         LocateResult* results) const;

  DatasetInfo info_;
  std::vector<std::array<Point2, 2>> edge_sample_;
  DomainOutline outline_;
  // The strategy refers to the mesh: declared first, destroyed last.
  std::shared_ptr<const ServingMesh> mesh_;
  std::unique_ptr<PointLocator> locator_;

  mutable std::atomic<uint64_t> queries_{0};
  mutable std::atomic<uint64_t> cost_sum_{0};
  mutable std::atomic<uint64_t> window_cost_{0};
  mutable std::atomic<uint64_t> window_count_{0};
  mutable std::atomic<double> last_window_mean_{-1};
  const std::unique_ptr<WalkCostHistogram> walk_costs_;
};

}  // namespace locator

#endif  // LOCATOR_ENGINE_H_
