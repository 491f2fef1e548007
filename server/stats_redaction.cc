#include "server/stats_redaction.h"

namespace locator {

EngineStats RedactStats(EngineStats stats) {
  // locator.proto documents an empty source as "redacted".
  stats.dataset.source.clear();
  // The state file's path, and errors about it, name the state dir.
  PersistenceSummary& persistence = stats.tuning.persistence;
  persistence.state_path.clear();
  if (!persistence.load_error.empty()) persistence.load_error = "<redacted>";
  if (!persistence.save_error.empty()) persistence.save_error = "<redacted>";
  return stats;
}

}  // namespace locator
