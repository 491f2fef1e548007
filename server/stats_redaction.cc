#include "server/stats_redaction.h"

namespace locator {

void RedactStats(v1::GetStatsResponse* response) {
  // locator.proto documents an empty source as "redacted".
  response->mutable_dataset()->clear_source();
}

}  // namespace locator
