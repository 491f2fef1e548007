#include "server/config/engine_flags.h"

#include <filesystem>
#include <string>

namespace locator {
namespace {

bool IsDirectory(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_directory(path, error);
}

}  // namespace

void AddEngineFlags(ServerConfig* config, FlagSet* flags) {
  EngineOptions& engine = config->engine;
  TuningOptions& tuning = engine.tuning;
  flags->Add("strategy", flag::Choice(&engine.strategy, StrategyNames()),
             "the point-location strategy");
  flags->Add("grid", flag::Count(&tuning.grid_size, 1, kMaxGridSize),
             "query histogram cells per side");
  flags->Add("warmup",
             flag::Count(&tuning.warmup_queries, 1, flag::kMaxOf<int64_t>),
             "adaptive-paper: queries counted before the hot regions are "
             "chosen");
  flags->Add("retune-every",
             flag::Count(&tuning.retune_every, 1, flag::kMaxOf<int64_t>),
             "self-tuning: re-tune after this many queries");
  flags->Add("budget",
             flag::Bytes(&tuning.budget_bytes, 0, flag::kMaxOf<int64_t>),
             "self-tuning: start table memory budget; 0 = 10% of the "
             "triangulation");
  flags->Add("stats-interval-s", flag::Seconds(&config->stats_interval_s),
             "log a stats line this often; 0 = never");
  flags->Add("retune-interval-s", flag::Seconds(&config->retune_interval_s),
             "also re-tune this often; 0 = only by query count");
  flags->Add("state-dir", flag::Text(&tuning.state_dir).Shape("DIR"),
             "self-tuning: directory where the learned tuning persists across "
             "restarts and reloads (a dataset named by NAME=SPEC keeps its "
             "files in DIR/NAME, made if missing); empty = off");
  flags->Add("mesh-cache", flag::Text(&engine.mesh_cache_dir).Shape("DIR"),
             "directory of serving-mesh files, one per dataset (named by its "
             "fingerprint): a start or reload maps the dataset's file instead "
             "of triangulating, and writes it after triangulating; empty = "
             "off");
}

Status CheckEngineFlags(const ServerConfig& config) {
  const EngineOptions& engine = config.engine;
  const std::string& state_dir = engine.tuning.state_dir;
  if (!state_dir.empty()) {
    if (!IsDirectory(state_dir)) {
      return FlagError("state-dir", state_dir, "not a directory");
    }
    if (engine.strategy != "self-tuning") {
      return FlagError("state-dir", state_dir,
                       "only the self-tuning strategy keeps state");
    }
  }
  if (!engine.mesh_cache_dir.empty() && !IsDirectory(engine.mesh_cache_dir)) {
    return FlagError("mesh-cache", engine.mesh_cache_dir, "not a directory");
  }
  return Status::OK();
}

}  // namespace locator
