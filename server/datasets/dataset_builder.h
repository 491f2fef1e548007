// DatasetBuilder: how locatord builds the engine of one of its datasets, at
// startup and on every reload: it loads the spec (LoadServedDataset; a
// raster or a dataset given max_error is simplified then; a BuildHeartbeat
// logs what the build is doing every 4 s), bounded by the datasets' shared
// point budget
// (--max-dataset-points is a total over all of them, see PointBudget; a
// successful build is published right after Build() returns, so it commits
// its points then), and triangulates it with the engine options, logging
// each step with the dataset's tag.
//
// With --mesh-cache DIR, a start or reload first looks for the dataset's
// mesh without reading the dataset: a plain generator spec's through its
// generated key (mesh_cache.h), any other spec's through its source key
// when its files have not changed since (source_key.h). Either is recorded
// after a build whose mesh file was written or mapped.
//
// With --state-dir DIR, the tuning of the dataset a bare --dataset gives
// persists in DIR, and that of a dataset named by NAME=SPEC in DIR/NAME
// (made if missing): state files are named by the dataset's fingerprint, so
// two datasets with the same points and options would otherwise share one.
//
// Owns the point budget. Thread-safety: Build() may run on several reload
// threads at once, one per dataset.

#ifndef LOCATOR_SERVER_DATASET_BUILDER_H_
#define LOCATOR_SERVER_DATASET_BUILDER_H_

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "locator/engine.h"
#include "locator/status.h"
#include "server/config/server_config.h"
#include "server/datasets/dataset_registry.h"
#include "server/datasets/dataset_source.h"
#include "server/serving/point_budget.h"

namespace locator {

class DatasetBuilder {
 public:
  // Builds datasets as `config` says; it must outlive the builder.
  explicit DatasetBuilder(const ServerConfig& config);

  // Builds the engine of `slot` from `spec` (a DatasetBuild). Before a
  // reload (`serving` set) it saves the serving engine's tuning, so that
  // reloading the same points continues from it; a failed reload is
  // logged. A dataset over the budget is ResourceExhausted with the
  // loader's message and a pointer to --max-dataset-points.
  Status Build(const DatasetSlot& slot, const std::string& spec,
               Engine* serving, BuiltDataset* built);

  // The tag of the log lines about `slot`: its name when the server holds
  // several datasets, else none.
  std::string_view Tag(const DatasetSlot& slot) const;

  // Writes `engine`'s learned tuning to its state file if it changed since
  // the last save; a failure is logged (with `tag`) and serving goes on.
  static void SaveTuningStateOrWarn(Engine& engine, std::string_view tag,
                                    std::string_view when);

 private:
  // Maps the mesh with `fingerprint` from the mesh cache as the engine of
  // `spec` (within the budget; stats report `origin`), logging that it was
  // found `how`, and returns true. False if that fails (logged unless it is
  // the budget): the caller loads the spec as usual.
  bool MapMesh(const DatasetSlot& slot, const std::string& spec,
               uint64_t fingerprint, DatasetOrigin origin,
               const EngineOptions& options, std::string_view how,
               std::shared_ptr<Engine>* built);
  // The engine of the tile set `spec` names (tile_set_source.h): its mesh
  // file mapped, outside the point budget (its memory is the page
  // cache's), and the tiles --tiles selects of it (all by default). The
  // manifest's, the selector's or the mesh file's error otherwise.
  Status MapTileSet(const DatasetSlot& slot, const std::string& spec,
                    EngineOptions options, BuiltDataset* built);
  // With --mesh-cache and a generator spec whose mesh was recorded there:
  // MapMesh without generating the points. False otherwise.
  bool MapGenerated(const DatasetSlot& slot, const std::string& spec,
                    const EngineOptions& options,
                    std::shared_ptr<Engine>* built);
  // With --mesh-cache and a source key of `spec` whose files are unchanged:
  // MapMesh without reading them. False otherwise (a key that does not
  // apply is logged, saying why).
  bool MapBySourceKey(const DatasetSlot& slot, const std::string& spec,
                      const EngineOptions& options,
                      std::shared_ptr<Engine>* built);
  // After a build from the generator spec `spec` whose mesh file was
  // written or mapped, records which mesh it generates (see
  // RecordGeneratedFingerprint); a failure is logged with `tag`.
  static void RecordGenerated(const std::string& spec,
                              const EngineOptions& options,
                              const MeshCacheOutcome& cache,
                              std::string_view tag);
  // After a build of `served` from `spec` whose mesh file was written or
  // mapped, records its source key when its files are known; a failure is
  // logged with `tag`.
  static void RecordSourceKey(const std::string& spec,
                              const EngineOptions& options,
                              const ServedDataset& served,
                              const DatasetInfo& info, std::string_view tag);
  // Loads `spec` within the budget and triangulates it.
  Status LoadAndTriangulate(const DatasetSlot& slot, const std::string& spec,
                            BuiltDataset* built);
  // The engine options of `slot` (its state dir), making that dir.
  Status EngineOptionsFor(const DatasetSlot& slot, EngineOptions* options);

  const ServerConfig& config_;
  PointBudget budget_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASET_BUILDER_H_
