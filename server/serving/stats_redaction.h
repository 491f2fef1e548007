// What `locatord --redact` hides: server paths, in the engine's statistics
// (RedactStats) and in the error messages sent to clients (RedactPaths).
//
// RedactStats is the one place that knows which EngineStats fields can
// reveal the server's file system: the dataset source (a file path, or a
// generator spec, cleared alike so that a client cannot tell the two
// apart), the mesh file's and the tuning state file's paths, with their
// load and save errors. A field added later that may hold a path is cleared
// here too. LocatorService applies it once, to the stats every output is
// made from (see LocatorService::OutputStats).
//
// RedactPaths keeps an error message precise ("FILE:LINE: reason") while
// replacing the paths in it: a failed Reload names the file the client
// asked for as the client named it. The server's logs keep the full paths:
// they are the operator's.
//
// Thread-safety: free functions.

#ifndef LOCATOR_SERVER_STATS_REDACTION_H_
#define LOCATOR_SERVER_STATS_REDACTION_H_

#include <string>
#include <string_view>
#include <vector>

#include "locator/engine.h"

namespace locator {

// `stats` with the fields that may name a path on the server cleared.
EngineStats RedactStats(EngineStats stats);

// What a redacted message shows instead of one text of the server's.
struct PathAlias {
  std::string path;   // as the server wrote it: a path, or a spec
  std::string shown;  // what the client sees instead
};

// `message` without server paths. A path starts the message or follows a
// space, a quote, '(', '=', '+' or ','; it ends the message or precedes a
// space, a quote, ':', '?', ',', ')' or '+'. Where an alias's path stands
// there as a whole, it is replaced by the alias's `shown` (the longest
// alias where several fit); every other absolute path is cut to its last
// component, so that "/srv/data/t.csv:3: reason" reads "t.csv:3: reason".
// Aliases with an empty path are ignored.
std::string RedactPaths(std::string_view message,
                        const std::vector<PathAlias>& aliases);

}  // namespace locator

#endif  // LOCATOR_SERVER_STATS_REDACTION_H_
