#include "server/datasets/dataset_registry.h"

#include <utility>

#include "common/input_text.h"

namespace locator {

DatasetSlot::DatasetSlot(size_t index, DatasetConfig config,
                         ReloadPolicy policy, DatasetBuild build)
    : index_(index),
      config_(std::move(config)),
      reload_policy_(std::move(policy)),
      reloader_(
          [this, build = std::move(build)](const std::string& spec,
                                           BuiltDataset* built) {
            if (!build) {
              return Status::FailedPrecondition("this server cannot reload");
            }
            return build(*this, spec.empty() ? config_.spec : spec,
                         serving().engine.get(), built);
          },
          [this](BuiltDataset built) { return Publish(std::move(built)); }) {}

DatasetSlot::Serving DatasetSlot::serving() const {
  MutexLock lock(&mu_);
  return Serving{built_.engine, built_.tiles, generation_};
}

uint64_t DatasetSlot::Publish(BuiltDataset built) {
  MutexLock lock(&mu_);
  built_ = std::move(built);
  return ++generation_;
}

Status DatasetSlot::StartReload(const std::string& spec,
                                EngineReloader::Done done) {
  return reloader_.Start(spec, std::move(done));
}

DatasetRegistry::DatasetRegistry(const std::vector<DatasetConfig>& datasets,
                                 const std::string& reload_dir,
                                 DatasetBuild build) {
  for (const DatasetConfig& config : datasets) {
    slots_.push_back(std::make_unique<DatasetSlot>(
        slots_.size(), config, ReloadPolicy(config.spec, reload_dir), build));
  }
}

Status DatasetRegistry::Find(std::string_view name, DatasetSlot** slot) const {
  if (name.empty()) {
    *slot = slots_.front().get();
    return Status::OK();
  }
  for (const std::unique_ptr<DatasetSlot>& candidate : slots_) {
    if (candidate->name() == name) {
      *slot = candidate.get();
      return Status::OK();
    }
  }
  std::string known;
  for (const std::unique_ptr<DatasetSlot>& candidate : slots_) {
    if (!known.empty()) known += ", ";
    known += candidate->name();
    if (candidate->is_default()) known += " (default)";
  }
  return Status::NotFound("unknown dataset " + QuotedInput(name) +
                          "; this server has: " + known);
}

}  // namespace locator
