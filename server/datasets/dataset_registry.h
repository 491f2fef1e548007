// DatasetRegistry: the named datasets one locatord serves, each in a
// DatasetSlot: its configured spec, its serving engine and generation, and
// the EngineReloader that builds its next engine.
//
// The set of datasets is fixed at construction (locatord's --dataset flags,
// in order; the first is the default); only what each slot serves changes.
// Slots are independent: each has its own engine, generation, reload and
// reload policy, so a reload (or a failed one) of one never touches
// another.
//
// Owns the slots. Thread-safety: Find(), slots() and every DatasetSlot
// method may be called from any thread.

#ifndef LOCATOR_SERVER_DATASET_REGISTRY_H_
#define LOCATOR_SERVER_DATASET_REGISTRY_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/mutex.h"
#include "locator/engine.h"
#include "locator/status.h"
#include "server/config/dataset_flag.h"
#include "server/datasets/engine_reloader.h"
#include "server/datasets/reload_policy.h"

namespace locator {

class DatasetSlot;

// Builds the engine for `slot` from `spec` (never empty: the slot's own spec
// when a reload names none), given the engine it serves now (null for its
// first build); runs on the slot's reload thread.
using DatasetBuild =
    std::function<Status(const DatasetSlot& slot, const std::string& spec,
                         Engine* serving, BuiltDataset* built)>;

class DatasetSlot {
 public:
  // What a slot serves at one moment.
  struct Serving {
    std::shared_ptr<Engine> engine;  // null while the first build runs
    // The tiles it serves, for a tile set (BuiltDataset); null otherwise.
    std::shared_ptr<const ShardTiles> tiles;
    uint64_t generation = 0;  // 1 for the first engine, +1 per reload
  };

  // Slot `index` of a registry, with `config`, reloading what `policy`
  // allows with `build`.
  DatasetSlot(size_t index, DatasetConfig config, ReloadPolicy policy,
              DatasetBuild build);

  DatasetSlot(const DatasetSlot&) = delete;
  DatasetSlot& operator=(const DatasetSlot&) = delete;

  // Its position among the registry's slots (flag order; 0 is the default).
  size_t index() const { return index_; }
  const std::string& name() const { return config_.name; }
  // The spec it was configured with.
  const std::string& spec() const { return config_.spec; }
  // Whether its flag named it (NAME=SPEC) rather than being a bare SPEC.
  bool named() const { return config_.named; }
  bool is_default() const { return index_ == 0; }
  const ReloadPolicy& reload_policy() const { return reload_policy_; }

  // The engine new calls use, and its generation.
  Serving serving() const EXCLUDES(mu_);
  // Makes `built` serve new calls; calls already running keep theirs.
  // Returns its generation.
  uint64_t Publish(BuiltDataset built) EXCLUDES(mu_);

  // Builds `spec` ("": the configured spec) on the slot's reload thread and
  // publishes it (see EngineReloader::Start). FailedPrecondition "reload in
  // progress" while a build of this slot runs.
  Status StartReload(const std::string& spec, EngineReloader::Done done);
  // Whether a build of this slot runs.
  bool reload_in_progress() const { return reloader_.in_progress(); }

 private:
  const size_t index_;
  const DatasetConfig config_;
  const ReloadPolicy reload_policy_;
  mutable Mutex mu_;
  BuiltDataset built_ GUARDED_BY(mu_);
  uint64_t generation_ GUARDED_BY(mu_) = 0;
  EngineReloader reloader_;  // last: its thread uses the members above
};

class DatasetRegistry {
 public:
  // One slot per entry of `datasets` (non-empty, names unique), in order;
  // a reload of a slot may load what ReloadPolicy(its spec, reload_dir)
  // allows, built by `build`.
  DatasetRegistry(const std::vector<DatasetConfig>& datasets,
                  const std::string& reload_dir, DatasetBuild build);

  // The slot named `name` ("": the default). NotFound "unknown dataset
  // 'NAME'; this server has: A (default), B" otherwise.
  Status Find(std::string_view name, DatasetSlot** slot) const;

  // Every slot, in flag order.
  const std::vector<std::unique_ptr<DatasetSlot>>& slots() const {
    return slots_;
  }
  DatasetSlot& default_slot() const { return *slots_.front(); }

 private:
  std::vector<std::unique_ptr<DatasetSlot>> slots_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASET_REGISTRY_H_
