// RedactStats: what `locatord --redact` leaves out of the engine's
// statistics.
//
// The one place that knows which EngineStats fields can reveal the server's
// file system: the dataset source (a file path, or a generator spec, cleared
// alike so that a client cannot tell the two apart), and the tuning state
// file's path, with its load and save errors. A field added later that may
// hold a path is cleared here too. LocatorService applies it once, to the
// stats every output is made from (see LocatorService::OutputStats).
//
// Thread-safety: a free function.

#ifndef LOCATOR_SERVER_STATS_REDACTION_H_
#define LOCATOR_SERVER_STATS_REDACTION_H_

#include "server/core/engine.h"

namespace locator {

// `stats` with the fields that may name a path on the server cleared.
EngineStats RedactStats(EngineStats stats);

}  // namespace locator

#endif  // LOCATOR_SERVER_STATS_REDACTION_H_
