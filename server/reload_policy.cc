#include "server/reload_policy.h"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>

#include "server/core/dataset.h"
#include "server/dataset_source.h"
#include "server/status_mapping.h"

namespace locator {
namespace {

namespace fs = std::filesystem;

bool HasDotDot(const fs::path& path) {
  for (const fs::path& part : path) {
    if (part == "..") return true;
  }
  return false;
}

// Whether `path` is `dir` itself or below it; both canonical.
bool IsInside(const fs::path& path, const fs::path& dir) {
  const auto [dir_end, path_at] =
      std::mismatch(dir.begin(), dir.end(), path.begin(), path.end());
  return dir_end == dir.end() && path_at != path.end();
}

}  // namespace

ReloadPolicy::ReloadPolicy(std::string configured_dataset,
                           std::string reload_dir)
    : configured_dataset_(std::move(configured_dataset)),
      reload_dir_(std::move(reload_dir)) {}

grpc::Status ReloadPolicy::Resolve(const std::string& requested,
                                   std::string* spec) const {
  if (requested.empty() || requested == configured_dataset_) {
    *spec = "";
    return grpc::Status::OK;
  }
  if (reload_dir_.empty()) {
    return ToGrpcStatus(Refusal::kPermissionDenied,
                        "this server reloads only its configured dataset "
                        "(start it with --reload-dir to allow others)");
  }
  *spec = ResolveInReloadDir(requested);
  if (spec->empty()) {
    return ToGrpcStatus(Refusal::kPermissionDenied,
                        "dataset '" + requested +
                            "' is not a file in this server's reload dir");
  }
  return grpc::Status::OK;
}

std::string ReloadPolicy::ResolveInReloadDir(
    const std::string& requested) const {
  std::string_view points;
  std::string_view wkt;
  if (SplitWktConstraintsSpec(requested, &points, &wkt)) {
    const std::string points_spec = ResolveInReloadDir(std::string(points));
    const std::string wkt_file = FileInReloadDir(std::string(wkt));
    if (points_spec.empty() || wkt_file.empty()) return "";
    return points_spec + "+" + wkt_file;
  }
  if (IsGeneratorSpec(requested)) return requested;
  // A spec's options ride along; its source must be a file in the dir.
  const gis::SpecParts parts = SplitServedSpec(requested);
  const std::string file = FileInReloadDir(std::string(parts.source));
  if (file.empty()) return "";
  // A file that reads others (mesh.ele reads mesh.node) is allowed only when
  // they are inside the dir too.
  for (const std::string& companion : DatasetCompanionFiles(file)) {
    if (FileInReloadDir(companion).empty()) return "";
  }
  return std::string(parts.prefix) + file + std::string(parts.options);
}

std::string ReloadPolicy::FileInReloadDir(const std::string& requested) const {
  const fs::path path(requested);
  if (HasDotDot(path)) return "";
  std::error_code error;
  const fs::path dir = fs::canonical(reload_dir_, error);
  if (error) return "";
  // canonical() resolves every symlink on the way, so the prefix test below
  // sees where the file really is.
  const fs::path file =
      fs::canonical(path.is_absolute() ? path : dir / path, error);
  if (error || !IsInside(file, dir) || !fs::is_regular_file(file, error)) {
    return "";
  }
  return file.string();
}

}  // namespace locator
