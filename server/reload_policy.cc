#include "server/reload_policy.h"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>

#include "common/gis/dataset_spec_options.h"
#include "common/gis/ogr_dataset_spec.h"
#include "common/gis/untrusted_ogr_spec.h"
#include "common/input_text.h"
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

// "dataset 'REQUESTED'", cut short: a request's text is echoed, not copied.
std::string DatasetQuoted(std::string_view requested) {
  return "dataset " + QuotedInput(requested);
}

grpc::Status NotInReloadDir(const std::string& requested) {
  return ToGrpcStatus(
      Refusal::kPermissionDenied,
      DatasetQuoted(requested) + " is not a file in this server's reload dir");
}

// `driver` as a spec option value (%-encoded: "ESRI Shapefile").
std::string DriverOption(std::string_view driver) {
  std::string encoded = "driver=";
  for (const char c : driver) encoded += c == ' ' ? "%20" : std::string(1, c);
  return encoded;
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
  return ResolveInReloadDir(requested, spec);
}

grpc::Status ReloadPolicy::ResolveInReloadDir(const std::string& requested,
                                              std::string* spec) const {
  std::string_view points;
  std::string_view wkt;
  if (SplitWktConstraintsSpec(requested, &points, &wkt)) {
    std::string points_spec;
    if (grpc::Status status =
            ResolveInReloadDir(std::string(points), &points_spec);
        !status.ok()) {
      return status;
    }
    const std::string wkt_file = FileInReloadDir(std::string(wkt));
    if (wkt_file.empty()) return NotInReloadDir(requested);
    *spec = points_spec + "+" + wkt_file;
    return grpc::Status::OK;
  }
  if (IsGeneratorSpec(requested)) {
    *spec = requested;
    return grpc::Status::OK;
  }
  if (DatasetKindOf(requested) == DatasetKind::kOgr) {
    return ResolveOgrSpec(requested, spec);
  }
  // A spec's options ride along; its source must be a file in the dir.
  const gis::SpecParts parts = SplitServedSpec(requested);
  const std::string file = FileInReloadDir(std::string(parts.source));
  if (file.empty()) return NotInReloadDir(requested);
  // A file that reads others (mesh.ele reads mesh.node) is allowed only when
  // they are inside the dir too.
  for (const std::string& companion : DatasetCompanionFiles(file)) {
    if (FileInReloadDir(companion).empty()) return NotInReloadDir(requested);
  }
  *spec = std::string(parts.prefix) + file + std::string(parts.options);
  return grpc::Status::OK;
}

grpc::Status ReloadPolicy::ResolveOgrSpec(const std::string& requested,
                                          std::string* spec) const {
  // The options are checked before the file, so that a refusal says
  // nothing about which files exist.
  // max_error and max_points, which every kind takes, only bound what is
  // built.
  gis::SimplifySpec simplify;
  std::string ogr_spec;
  gis::OgrDatasetSpec parsed;
  if (Status status = gis::TakeSimplifyOptions(requested, &simplify, &ogr_spec);
      !status.ok()) {
    return ToGrpcStatus(status);
  }
  if (Status status = gis::ParseOgrDatasetSpec(ogr_spec, &parsed);
      !status.ok()) {
    return ToGrpcStatus(status);
  }
  if (Status status = gis::CheckUntrustedOgrOptions(parsed); !status.ok()) {
    return ToGrpcStatus(Refusal::kPermissionDenied,
                        DatasetQuoted(requested) + ": " + status.message());
  }
  const gis::SpecParts parts = gis::SplitOgrDatasetSpec(requested);
  const std::string file = FileInReloadDir(std::string(parts.source));
  if (file.empty()) return NotInReloadDir(requested);
  std::string driver;
  if (Status status = gis::UntrustedOgrDriver(parsed, file, &driver);
      !status.ok()) {
    return ToGrpcStatus(Refusal::kPermissionDenied,
                        DatasetQuoted(requested) + ": " + status.message());
  }
  // The load may open the file with this driver only.
  *spec = std::string(parts.prefix) + file + std::string(parts.options);
  if (parsed.driver.empty()) {
    spec->push_back(parts.options.empty() ? '?' : '&');
    spec->append(DriverOption(driver));
  }
  return grpc::Status::OK;
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
