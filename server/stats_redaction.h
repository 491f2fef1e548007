// RedactStats: what `locatord --redact` leaves out of GetStats answers.
//
// The one place that knows which GetStatsResponse fields can reveal the
// server's file system: the dataset source (a file path, or a generator
// spec, cleared alike so that a client cannot tell the two apart), and the
// tuning state file's path, with its load and save errors. A field added
// later that may hold a path is cleared here too.
//
// Thread-safety: a free function.

#ifndef LOCATOR_SERVER_STATS_REDACTION_H_
#define LOCATOR_SERVER_STATS_REDACTION_H_

#include "locator/v1/locator.pb.h"

namespace locator {

// Clears the fields of `response` that may name a path on the server.
void RedactStats(v1::GetStatsResponse* response);

}  // namespace locator

#endif  // LOCATOR_SERVER_STATS_REDACTION_H_
