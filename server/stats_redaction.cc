#include "server/stats_redaction.h"

namespace locator {

void RedactStats(v1::GetStatsResponse* response) {
  // locator.proto documents an empty source as "redacted".
  response->mutable_dataset()->clear_source();
  // The state file's path, and errors about it, name the state dir.
  v1::TuningPersistence* persistence =
      response->mutable_tuning()->mutable_persistence();
  persistence->clear_state_path();
  if (!persistence->load_error().empty()) {
    persistence->set_load_error("<redacted>");
  }
  if (!persistence->save_error().empty()) {
    persistence->set_save_error("<redacted>");
  }
}

}  // namespace locator
