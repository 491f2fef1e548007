#include "server/dataset_builder.h"

#include <chrono>
#include <filesystem>
#include <system_error>
#include <utility>

#include "server/core/dataset.h"
#include "server/dataset_source.h"
#include "server/server_log.h"

namespace locator {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// Says where a new engine's tuning came from, and why a state file in the
// state dir was ignored.
void LogTuningState(const Engine& engine, std::string_view tag) {
  const PersistenceSummary p = engine.Stats().tuning.persistence;
  if (p.state_path.empty()) return;
  if (p.restored_from_state) {
    LogLine(tag) << "restored the tuning state from " << p.state_path;
  } else if (!p.load_error.empty()) {
    LogLine(tag) << "warning: ignoring the tuning state " << p.state_path
                 << ": " << p.load_error;
  } else {
    LogLine(tag) << "no tuning state at " << p.state_path << " yet";
  }
}

// Says whether the mesh was mapped from the mesh cache, and why a file there
// was ignored or could not be written.
void LogMeshCache(const MeshCacheOutcome& cache, std::string_view tag) {
  if (cache.path.empty()) return;
  if (cache.mapped) {
    LogLine(tag) << "mapped the serving mesh from " << cache.path;
    return;
  }
  if (!cache.load_error.empty()) {
    LogLine(tag) << "warning: ignoring the mesh file " << cache.path << ": "
                 << cache.load_error << "; triangulated instead";
  }
  if (cache.save_error.empty()) {
    LogLine(tag) << "wrote the serving mesh to " << cache.path;
  } else {
    LogLine(tag) << "warning: cannot write the mesh file " << cache.path << ": "
                 << cache.save_error;
  }
}

}  // namespace

DatasetBuilder::DatasetBuilder(const ServerConfig& config)
    : config_(config),
      budget_(config.dataset_limits.max_points, config.datasets.size()) {}

std::string_view DatasetBuilder::Tag(const DatasetSlot& slot) const {
  return config_.datasets.size() > 1 ? std::string_view(slot.name())
                                     : std::string_view();
}

void DatasetBuilder::SaveTuningStateOrWarn(Engine& engine, std::string_view tag,
                                           std::string_view when) {
  const Status status = engine.SaveTuningState();
  if (!status.ok()) {
    LogLine(tag) << "warning: cannot save the tuning state " << when << ": "
                 << status.ToString();
  }
}

Status DatasetBuilder::EngineOptionsFor(const DatasetSlot& slot,
                                        EngineOptions* options) {
  *options = config_.engine;
  std::string& dir = options->tuning.state_dir;
  if (dir.empty() || !slot.named()) return Status::OK();
  dir = (std::filesystem::path(dir) / slot.name()).string();
  std::error_code error;
  std::filesystem::create_directory(dir, error);
  if (error) {
    return Status::IOError("cannot make the state dir " + dir + ": " +
                           error.message());
  }
  return Status::OK();
}

Status DatasetBuilder::LoadAndTriangulate(const DatasetSlot& slot,
                                          const std::string& spec,
                                          std::shared_ptr<Engine>* built) {
  const std::string_view tag = Tag(slot);
  EngineOptions options;
  if (Status status = EngineOptionsFor(slot, &options); !status.ok()) {
    return status;
  }
  LogLine(tag) << "loading dataset " << spec;
  const auto load_start = std::chrono::steady_clock::now();
  Dataset dataset;
  DatasetLimits limits = config_.dataset_limits;
  limits.max_points = budget_.Available(slot.index());
  Status status = LoadServedDataset(spec, limits, &dataset);
  if (status.ok()) status = budget_.Claim(slot.index(), dataset.points.size());
  if (status.code() == Status::Code::kResourceExhausted) {
    const std::string see =
        config_.datasets.size() == 1
            ? " (see --max-dataset-points)"
            : " (see --max-dataset-points: a total of " +
                  std::to_string(budget_.total()) +
                  " points over all datasets, of which the others hold " +
                  std::to_string(budget_.HeldByOthers(slot.index())) + ")";
    return Status::ResourceExhausted(status.message() + see);
  }
  if (!status.ok()) return status;
  LogLine(tag) << "loaded " << dataset.points.size() << " points in "
               << SecondsSince(load_start) << " s; building the serving mesh";
  std::unique_ptr<Engine> created;
  status = Engine::Create(std::move(dataset), options, &created);
  if (!status.ok()) {
    budget_.Cancel(slot.index());
    return status;
  }
  // Published by the caller right after this returns.
  budget_.Commit(slot.index());
  const DatasetInfo& info = created->dataset_info();
  LogLine(tag) << (info.mesh_cache.mapped ? "mapped " : "built ")
               << info.triangles << " triangles over " << info.vertices
               << " vertices (" << info.duplicates_merged
               << " duplicates merged) in " << info.build_seconds << " s";
  LogMeshCache(info.mesh_cache, tag);
  LogTuningState(*created, tag);
  *built = std::move(created);
  return Status::OK();
}

Status DatasetBuilder::Build(const DatasetSlot& slot, const std::string& spec,
                             Engine* serving, std::shared_ptr<Engine>* built) {
  if (serving != nullptr) {
    SaveTuningStateOrWarn(*serving, Tag(slot), "before the reload");
  }
  const Status status = LoadAndTriangulate(slot, spec, built);
  if (!status.ok() && serving != nullptr) {
    LogLine(Tag(slot)) << "reload failed, still serving the previous dataset: "
                       << status.ToString();
  }
  return status;
}

}  // namespace locator
