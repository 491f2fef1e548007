#include "server/datasets/dataset_builder.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>
#include <thread>
#include <utility>

#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "server/config/server_log.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/datasets/build_heartbeat.h"
#include "server/datasets/dataset_source.h"
#include "server/datasets/source_key.h"
#include "server/datasets/tile_set_source.h"

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
    LogLine(LogLevel::kInfo, tag)
        << "restored the tuning state from " << p.state_path;
  } else if (!p.load_error.empty()) {
    LogLine(LogLevel::kWarning, tag)
        << "ignoring the tuning state " << p.state_path << ": " << p.load_error;
  } else {
    LogLine(LogLevel::kInfo, tag)
        << "no tuning state at " << p.state_path << " yet";
  }
}

// Says whether the mesh was mapped from the mesh cache, and why a file there
// was ignored or could not be written.
void LogMeshCache(const MeshCacheOutcome& cache, std::string_view tag) {
  if (cache.path.empty()) return;
  if (cache.mapped) {
    LogLine(LogLevel::kInfo, tag)
        << "mapped the serving mesh from " << cache.path;
    return;
  }
  if (!cache.load_error.empty()) {
    LogLine(LogLevel::kWarning, tag)
        << "ignoring the mesh file " << cache.path << ": " << cache.load_error
        << "; triangulated instead";
  }
  if (cache.save_error.empty()) {
    LogLine(LogLevel::kInfo, tag) << "wrote the serving mesh to " << cache.path;
  } else {
    LogLine(LogLevel::kWarning, tag) << "cannot write the mesh file "
                                     << cache.path << ": " << cache.save_error;
  }
}

// Says how a new engine's mesh came to be, and where its tuning came from.
void LogBuilt(const Engine& engine, std::string_view tag) {
  const DatasetInfo& info = engine.dataset_info();
  LogLine(LogLevel::kInfo, tag)
      << (info.mesh_cache.mapped ? "mapped " : "built ") << info.triangles
      << " triangles over " << info.vertices << " vertices ("
      << info.duplicates_merged << " duplicates merged) in "
      << info.build_seconds << " s";
  LogMeshCache(info.mesh_cache, tag);
  LogTuningState(engine, tag);
}

// How often a build says what it is doing (at least every 5 s).
constexpr std::chrono::seconds kProgressInterval{4};

// Says what a simplification made of its source (the certificate).
void LogSimplified(const SimplificationStats& s, std::string_view tag) {
  LogLine(LogLevel::kInfo, tag)
      << "simplified " << s.source_samples << " source samples to "
      << s.vertices << " vertices and " << s.triangles << " triangles in "
      << s.build_seconds << " s: max error " << s.max_error << " (target "
      << s.target_error << ", max_points " << s.max_points << ", "
      << s.unserved_samples << " samples outside the domain)";
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
    LogLine(LogLevel::kWarning, tag)
        << "cannot save the tuning state " << when << ": " << status.ToString();
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
                                          BuiltDataset* built) {
  const std::string_view tag = Tag(slot);
  EngineOptions options;
  if (Status status = EngineOptionsFor(slot, &options); !status.ok()) {
    return status;
  }
  if (IsTileSetSpec(spec)) return MapTileSet(slot, spec, options, built);
  if (MapGenerated(slot, spec, options, &built->engine) ||
      MapBySourceKey(slot, spec, options, &built->engine)) {
    return Status::OK();
  }
  LogLine(LogLevel::kInfo, tag) << "loading dataset " << spec;
  const auto load_start = std::chrono::steady_clock::now();
  BuildHeartbeat heartbeat(
      [tag](const std::string& line) { LogLine(LogLevel::kInfo, tag) << line; },
      kProgressInterval);
  ServedLoadOptions load;
  load.limits = config_.dataset_limits;
  load.limits.max_points = budget_.Available(slot.index());
  load.threads = std::max(1u, std::thread::hardware_concurrency());
  load.progress = [&heartbeat](const TinProgress& p) { heartbeat.Report(p); };
  load.progress_interval_s =
      std::chrono::duration<double>(kProgressInterval).count();
  ServedDataset served;
  Status status = LoadServedDataset(spec, load, &served);
  if (status.ok()) {
    status = budget_.Claim(slot.index(), served.dataset.points.size());
  }
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
  LogLine(LogLevel::kInfo, tag)
      << "loaded " << served.dataset.points.size() << " points in "
      << SecondsSince(load_start) << " s; building the serving mesh";
  if (served.simplification) LogSimplified(*served.simplification, tag);
  heartbeat.SetPhase("building the serving mesh");
  StatusOr<std::unique_ptr<Engine>> engine =
      served.simplification
          ? Engine::CreateSimplified(std::move(served.dataset),
                                     *served.simplification, options)
          : Engine::Create(std::move(served.dataset), options);
  if (!engine.ok()) {
    budget_.Cancel(slot.index());
    return std::move(engine).status();
  }
  std::unique_ptr<Engine> created = *std::move(engine);
  // Published by the caller right after this returns.
  budget_.Commit(slot.index());
  const DatasetInfo& info = created->dataset_info();
  RecordGenerated(spec, options, info.mesh_cache, tag);
  RecordSourceKey(spec, options, served, info, tag);
  LogBuilt(*created, tag);
  built->engine = std::move(created);
  return Status::OK();
}

bool DatasetBuilder::MapMesh(const DatasetSlot& slot, const std::string& spec,
                             uint64_t fingerprint, DatasetOrigin origin,
                             const EngineOptions& options, std::string_view how,
                             std::shared_ptr<Engine>* built) {
  const std::string_view tag = Tag(slot);
  StatusOr<std::unique_ptr<Engine>> created =
      Engine::CreateFromMeshFile(fingerprint, std::move(origin), options);
  Status status = created.status();
  if (status.ok()) {
    status =
        budget_.Claim(slot.index(), (*created)->dataset_info().input_points);
  }
  if (!status.ok()) {
    // The slow path loads the spec and says what is wrong, if anything.
    if (status.code() != Status::Code::kResourceExhausted) {
      LogLine(LogLevel::kWarning, tag)
          << "cannot map the mesh of " << spec << ": " << status.ToString()
          << "; loading it instead";
    }
    return false;
  }
  budget_.Commit(slot.index());
  LogLine(LogLevel::kInfo, tag) << "found the mesh of " << spec << " " << how;
  LogBuilt(**created, tag);
  *built = *std::move(created);
  return true;
}

Status DatasetBuilder::MapTileSet(const DatasetSlot& slot,
                                  const std::string& spec,
                                  EngineOptions options, BuiltDataset* built) {
  TileSetManifestSummary manifest;
  RETURN_IF_ERROR(ReadTileSetSpec(spec, &manifest, &options.mesh_cache_dir));
  if (manifest.mesh_file != MeshFilePath("", manifest.fingerprint)) {
    return Status::InvalidArgument(spec + ": mesh_file '" + manifest.mesh_file +
                                   "' is not the fingerprint's mesh file");
  }
  ASSIGN_OR_RETURN(TileRouter router,
                   TileRouter::Create(manifest.bounds, manifest.grid_level,
                                      manifest.tile_first_cells));
  StatusOr<std::shared_ptr<const ShardTiles>> tiles = ShardTiles::Select(
      std::move(router), config_.tiles, manifest.fingerprint);
  if (!tiles.ok()) {
    return Status::InvalidArgument(spec + ": " + tiles.status().message());
  }
  LogLine(LogLevel::kInfo, Tag(slot))
      << "mapping the tile set " << spec << " (" << manifest.source << ", "
      << manifest.input_points << " points), serving "
      << (*tiles)->served().size() << " of its "
      << (*tiles)->router().num_tiles() << " tiles";
  DatasetOrigin origin;
  origin.source = manifest.source;
  origin.crs = manifest.crs;
  options.tuning.mesh_larger_than_memory = true;
  ASSIGN_OR_RETURN(std::unique_ptr<Engine> engine,
                   Engine::CreateFromMeshFile(manifest.fingerprint,
                                              std::move(origin), options));
  LogBuilt(*engine, Tag(slot));
  built->engine = std::move(engine);
  built->tiles = *std::move(tiles);
  return Status::OK();
}

bool DatasetBuilder::MapGenerated(const DatasetSlot& slot,
                                  const std::string& spec,
                                  const EngineOptions& options,
                                  std::shared_ptr<Engine>* built) {
  if (options.mesh_cache_dir.empty() || !IsGeneratorSpec(spec)) return false;
  const StatusOr<GeneratorSpec> generator = ParseGeneratorSpec(spec);
  uint64_t fingerprint = 0;
  if (!generator.ok() || !FindGeneratedFingerprint(options.mesh_cache_dir,
                                                   *generator, &fingerprint)
                              .ok()) {
    return false;
  }
  DatasetOrigin origin;
  origin.source = spec;
  return MapMesh(slot, spec, fingerprint, std::move(origin), options,
                 "without generating it", built);
}

bool DatasetBuilder::MapBySourceKey(const DatasetSlot& slot,
                                    const std::string& spec,
                                    const EngineOptions& options,
                                    std::shared_ptr<Engine>* built) {
  if (options.mesh_cache_dir.empty()) return false;
  SourceKey key;
  Status status = ReadSourceKey(options.mesh_cache_dir, spec, &key);
  if (status.code() == Status::Code::kNotFound) return false;
  if (status.ok()) status = CheckSourceFiles(key);
  if (!status.ok()) {
    LogLine(LogLevel::kInfo, Tag(slot)) << "not mapping the cached mesh of "
                                        << spec << ": " << status.message();
    return false;
  }
  DatasetOrigin origin;
  origin.source = spec;
  origin.crs = std::move(key.crs);
  origin.simplification = key.simplification;
  return MapMesh(slot, spec, key.fingerprint, std::move(origin), options,
                 "by the identity of its files, without reading them", built);
}

void DatasetBuilder::RecordGenerated(const std::string& spec,
                                     const EngineOptions& options,
                                     const MeshCacheOutcome& cache,
                                     std::string_view tag) {
  if (cache.path.empty() || !cache.save_error.empty() ||
      !IsGeneratorSpec(spec)) {
    return;
  }
  const StatusOr<GeneratorSpec> generator = ParseGeneratorSpec(spec);
  if (!generator.ok()) return;
  const Status status = RecordGeneratedFingerprint(
      options.mesh_cache_dir, *generator, cache.fingerprint);
  if (!status.ok()) {
    LogLine(LogLevel::kWarning, tag)
        << "cannot record the mesh of " << spec << ": " << status.ToString();
  }
}

void DatasetBuilder::RecordSourceKey(const std::string& spec,
                                     const EngineOptions& options,
                                     const ServedDataset& served,
                                     const DatasetInfo& info,
                                     std::string_view tag) {
  const MeshCacheOutcome& cache = info.mesh_cache;
  if (cache.path.empty() || !cache.save_error.empty() || served.files.empty()) {
    return;
  }
  SourceKey key;
  for (const std::string& file : served.files) {
    key.files.push_back(IdentifyFile(file));
  }
  for (const std::string& file : served.absent_files) {
    key.files.push_back(IdentifyFile(file));
  }
  key.fingerprint = cache.fingerprint;
  key.crs = info.crs;
  key.simplification = info.simplification;
  if (const Status status = WriteSourceKey(options.mesh_cache_dir, spec, key);
      !status.ok()) {
    LogLine(LogLevel::kWarning, tag)
        << "cannot record the mesh of " << spec << ": " << status.ToString();
  }
}

Status DatasetBuilder::Build(const DatasetSlot& slot, const std::string& spec,
                             Engine* serving, BuiltDataset* built) {
  if (serving != nullptr) {
    SaveTuningStateOrWarn(*serving, Tag(slot), "before the reload");
  }
  const Status status = LoadAndTriangulate(slot, spec, built);
  if (!status.ok() && serving != nullptr) {
    LogLine(LogLevel::kWarning, Tag(slot))
        << "reload failed, still serving the previous dataset: "
        << status.ToString();
  }
  return status;
}

}  // namespace locator
