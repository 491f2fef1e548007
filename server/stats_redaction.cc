#include "server/stats_redaction.h"

namespace locator {

EngineStats RedactStats(EngineStats stats) {
  // locator.proto documents an empty source as "redacted".
  stats.dataset.source.clear();
  // The mesh file's and the state file's paths, and errors about them, name
  // their directories.
  MeshCacheOutcome& cache = stats.dataset.mesh_cache;
  cache.path.clear();
  if (!cache.load_error.empty()) cache.load_error = "<redacted>";
  if (!cache.save_error.empty()) cache.save_error = "<redacted>";
  PersistenceSummary& persistence = stats.tuning.persistence;
  persistence.state_path.clear();
  if (!persistence.load_error.empty()) persistence.load_error = "<redacted>";
  if (!persistence.save_error.empty()) persistence.save_error = "<redacted>";
  return stats;
}

}  // namespace locator
