// Source keys: how a start finds the mesh of a file dataset in the mesh
// cache (locatord --mesh-cache DIR) without reading the dataset's files.
//
// After a build whose mesh file was written or mapped, the builder records
// DIR/source-<16 hex digits>.key, named by an XXH3 digest of the spec, the
// working directory (a spec's relative paths resolve against it) and the
// key format's version. It holds the spec and the directory, the identity of
// every file the dataset was read from (absolute path, size, modification
// time in nanoseconds, device and inode) and of the side-cars that did not
// exist, the fingerprint of the dataset the mesh was built from (which names
// its mesh file), the dataset's CRS and simplification certificate, and last
// an XXH3 checksum of the rest. A later start with the same spec in the same
// directory, whose files all still have the recorded identity, maps the mesh
// by that fingerprint without opening them: a restart serves a DEM in the
// time it takes to map its mesh.
//
// Trust. The identity is trusted as make trusts modification times: a file
// replaced (another inode), resized or written (a new mtime) is noticed,
// and the dataset is then read again and its key rewritten; a file
// rewritten in place to the same size with its old mtime put back on purpose
// (touch -d) is not. The mesh file itself is checked as always
// (mesh_file.h), and the checksum catches a damaged key.
//
// Thread-safety: free functions. Key files are written atomically, so
// processes may share a cache directory.

#ifndef LOCATOR_SERVER_SOURCE_KEY_H_
#define LOCATOR_SERVER_SOURCE_KEY_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"
#include "server/core/terrain/tin_options.h"

namespace locator {

// What stat() says of a file: enough to notice that it changed.
struct FileIdentity {
  std::string path;
  bool exists = false;
  uint64_t size = 0;
  int64_t mtime_ns = 0;
  uint64_t device = 0;
  uint64_t inode = 0;

  bool operator==(const FileIdentity&) const = default;
};

// The identity of the file at `path` now (exists false when there is none
// or it cannot be stat'ed).
FileIdentity IdentifyFile(const std::string& path);

struct SourceKey {
  std::vector<FileIdentity> files;
  uint64_t fingerprint = 0;
  std::string crs;
  std::optional<SimplificationStats> simplification;
};

// The key file of `spec` (read in the current working directory) in
// `cache_dir`.
std::string SourceKeyPath(const std::string& cache_dir, std::string_view spec);

// Reads the key of `spec` from `cache_dir`. NotFound without one;
// InvalidArgument naming the file and what is wrong when it is not a key
// (bad checksum, another spec or directory, malformed).
Status ReadSourceKey(const std::string& cache_dir, std::string_view spec,
                     SourceKey* out);

// OK when every file of `key` still has its recorded identity;
// FailedPrecondition naming the first that does not.
Status CheckSourceFiles(const SourceKey& key);

// Writes the key of `spec` to `cache_dir` atomically (IOError naming the
// step that failed).
Status WriteSourceKey(const std::string& cache_dir, std::string_view spec,
                      const SourceKey& key);

}  // namespace locator

#endif  // LOCATOR_SERVER_SOURCE_KEY_H_
