// ReloadPolicy: which datasets a Reload RPC may load.
//
// The configured dataset may always be reloaded: an empty spec, or the
// --dataset spec itself. Anything else needs --reload-dir DIR:
//   - a generator spec (uniform:, clusters:), bounded by --max-dataset-points
//     like --dataset (LoadDataset enforces the limit);
//   - a file inside DIR, named by a path relative to DIR, or absolute. It is
//     resolved with realpath, and must then be a regular file inside DIR: no
//     ".." component and no symlink leading out of DIR;
//   - a spec with options (SOURCE?OPTIONS: an OGR source, a raster, a LAS
//     file, any spec given max_error; see SplitServedSpec) whose source is
//     such a file; its options are kept as given;
//   - POINTS+PATH.wkt where POINTS is any of the above and PATH.wkt a file
//     inside DIR; a .ele needs its .node inside DIR too.
// Every other spec is refused alike (PERMISSION_DENIED), whether or not the
// file exists, so that a caller learns nothing about the server's files.
//
// Immutable after construction; thread-safe.

#ifndef LOCATOR_SERVER_RELOAD_POLICY_H_
#define LOCATOR_SERVER_RELOAD_POLICY_H_

#include <grpcpp/support/status.h>

#include <string>

namespace locator {

class ReloadPolicy {
 public:
  // Only the configured dataset, whatever it is ("" only).
  ReloadPolicy() = default;
  // `reload_dir` empty: only `configured_dataset` (and "").
  ReloadPolicy(std::string configured_dataset, std::string reload_dir);

  // OK with `*spec` set to what to load for a Reload of `requested`: "" for
  // the configured dataset, the generator spec, or the file's resolved path.
  // PERMISSION_DENIED otherwise.
  grpc::Status Resolve(const std::string& requested, std::string* spec) const;

 private:
  // What to load for `requested` (not the configured dataset): the
  // generator spec, or the spec with its file(s) resolved; "" if refused.
  std::string ResolveInReloadDir(const std::string& requested) const;
  // The file of `requested` inside reload_dir_, resolved; "" if there is none.
  std::string FileInReloadDir(const std::string& requested) const;

  std::string configured_dataset_;
  std::string reload_dir_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_RELOAD_POLICY_H_
