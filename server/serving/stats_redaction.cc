#include "server/serving/stats_redaction.h"

namespace locator {
namespace {

// What may come right before a path in a message, and what ends one.
constexpr std::string_view kBeforePath = " \t'\"`(=+,";
constexpr std::string_view kAfterPath = " \t'\"`:?,)+";

// Whether a path (or an alias's) may start at `at`: at the start, or after
// one of kBeforePath.
bool PathMayStart(std::string_view message, size_t at) {
  return at == 0 || kBeforePath.find(message[at - 1]) != std::string_view::npos;
}

// Whether a path may end at `at`: at the end, or before one of kAfterPath.
bool PathMayEnd(std::string_view message, size_t at) {
  return at == message.size() ||
         kAfterPath.find(message[at]) != std::string_view::npos;
}

// The last component of `path` ("t.csv" of "/srv/data/t.csv"; "data" of
// "/srv/data/"); `path` itself when it has none ("/").
std::string_view LastComponent(std::string_view path) {
  while (path.size() > 1 && path.back() == '/') path.remove_suffix(1);
  if (path.size() <= 1) return path;
  return path.substr(path.rfind('/') + 1);
}

// The longest alias whose path is in `message` at `at`, as a whole; null if
// there is none.
const PathAlias* AliasAt(std::string_view message, size_t at,
                         const std::vector<PathAlias>& aliases) {
  const PathAlias* best = nullptr;
  for (const PathAlias& alias : aliases) {
    if (!alias.path.empty() && message.substr(at).starts_with(alias.path) &&
        PathMayEnd(message, at + alias.path.size()) &&
        (best == nullptr || alias.path.size() > best->path.size())) {
      best = &alias;
    }
  }
  return best;
}

}  // namespace

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

std::string RedactPaths(std::string_view message,
                        const std::vector<PathAlias>& aliases) {
  std::string redacted;
  size_t at = 0;
  while (at < message.size()) {
    const PathAlias* alias =
        PathMayStart(message, at) ? AliasAt(message, at, aliases) : nullptr;
    if (alias != nullptr) {
      redacted += alias->shown;
      at += alias->path.size();
    } else if (message[at] == '/' && PathMayStart(message, at)) {
      size_t end = at + 1;
      while (!PathMayEnd(message, end)) ++end;
      redacted += LastComponent(message.substr(at, end - at));
      at = end;
    } else {
      redacted += message[at++];
    }
  }
  return redacted;
}

}  // namespace locator
