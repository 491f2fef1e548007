// ReloadPolicy: which datasets a Reload RPC may load.
//
// The configured dataset may always be reloaded: an empty spec, or the
// --dataset spec itself. Anything else needs --reload-dir DIR:
//   - a generator spec (uniform:, clusters:), bounded by --max-dataset-points
//     like --dataset (LoadDataset enforces the limit);
//   - a file inside DIR, named by a path relative to DIR, or absolute. It is
//     resolved with realpath, and must then be a regular file inside DIR: no
//     ".." component and no symlink leading out of DIR;
//   - a spec with options (SOURCE?OPTIONS, see SplitServedSpec) whose source
//     is such a file, and whose options a request may use. Every kind may
//     take max_error= and max_points=, and a LAS file classes= and returns=.
//     An OGR source (common/gis/untrusted_ogr_spec.h: a few drivers and
//     harmless open options, a plain where clause, an a_srs that passes the
//     request CRS policy) or a raster (common/gis/untrusted_raster_spec.h: a
//     few drivers that read no file the raster names, band=, such an a_srs)
//     is read with the one driver that identified it (driver= is added to
//     the spec). A text file takes no other option;
//   - POINTS+PATH.wkt where POINTS is any of the above and PATH.wkt a file
//     inside DIR; a .ele needs its .node inside DIR too.
// Every other spec is refused alike (PERMISSION_DENIED), whether or not the
// file exists, so that a caller learns nothing about the server's files; a
// GIS option a request may not use is refused (PERMISSION_DENIED, naming
// it) before the file is looked at.
//
// Immutable after construction; thread-safe.

#ifndef LOCATOR_SERVER_RELOAD_POLICY_H_
#define LOCATOR_SERVER_RELOAD_POLICY_H_

#include <string>

#include "locator/status_or.h"

namespace locator {

class ReloadPolicy {
 public:
  // Only the configured dataset, whatever it is ("" only).
  ReloadPolicy() = default;
  // `reload_dir` empty: only `configured_dataset` (and "").
  ReloadPolicy(std::string configured_dataset, std::string reload_dir);

  // What to load for a Reload of `requested`: "" for the configured
  // dataset, the generator spec, or the spec with its file's resolved path.
  // PERMISSION_DENIED otherwise; INVALID_ARGUMENT for a spec whose options do
  // not parse.
  StatusOr<std::string> Resolve(const std::string& requested) const;

 private:
  // What to load for `requested` (not the configured dataset): the
  // generator spec, or the spec with its file(s) resolved.
  StatusOr<std::string> ResolveInReloadDir(const std::string& requested) const;
  // ResolveInReloadDir for a spec that names a file (any kind but a
  // generator): its options checked, its file resolved, its driver chosen.
  StatusOr<std::string> ResolveFileSpec(const std::string& requested) const;
  // The file of `requested` inside reload_dir_, resolved; "" if there is none.
  std::string FileInReloadDir(const std::string& requested) const;

  std::string configured_dataset_;
  std::string reload_dir_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_RELOAD_POLICY_H_
