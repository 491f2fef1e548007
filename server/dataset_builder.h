// DatasetBuilder: how locatord builds the engine of one of its datasets, at
// startup and on every reload: it loads the spec (LoadServedDataset; a
// raster or a dataset given max_error is simplified then, its progress
// logged every few seconds), bounded by the datasets' shared point budget
// (--max-dataset-points is a total over all of them, see PointBudget; a
// successful build is published right after Build() returns, so it commits
// its points then), and triangulates it with the engine options, logging
// each step with the dataset's tag.
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

#include <memory>
#include <string>
#include <string_view>

#include "common/status.h"
#include "server/core/engine.h"
#include "server/dataset_registry.h"
#include "server/point_budget.h"
#include "server/server_config.h"

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
               Engine* serving, std::shared_ptr<Engine>* built);

  // The tag of the log lines about `slot`: its name when the server holds
  // several datasets, else none.
  std::string_view Tag(const DatasetSlot& slot) const;

  // Writes `engine`'s learned tuning to its state file if it changed since
  // the last save; a failure is logged (with `tag`) and serving goes on.
  static void SaveTuningStateOrWarn(Engine& engine, std::string_view tag,
                                    std::string_view when);

 private:
  // With --mesh-cache and a generator spec whose mesh was recorded there:
  // maps it without generating the points (within the budget) and returns
  // true. False if any of that does not hold or fails (a failure but the
  // budget is logged): the caller loads the spec as usual.
  bool MapGenerated(const DatasetSlot& slot, const std::string& spec,
                    const EngineOptions& options,
                    std::shared_ptr<Engine>* built);
  // After a build from the generator spec `spec` whose mesh file was
  // written or mapped, records which mesh it generates (see
  // RecordGeneratedFingerprint); a failure is logged with `tag`.
  static void RecordGenerated(const std::string& spec,
                              const EngineOptions& options,
                              const MeshCacheOutcome& cache,
                              std::string_view tag);
  // Loads `spec` within the budget and triangulates it.
  Status LoadAndTriangulate(const DatasetSlot& slot, const std::string& spec,
                            std::shared_ptr<Engine>* built);
  // The engine options of `slot` (its state dir), making that dir.
  Status EngineOptionsFor(const DatasetSlot& slot, EngineOptions* options);

  const ServerConfig& config_;
  PointBudget budget_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASET_BUILDER_H_
