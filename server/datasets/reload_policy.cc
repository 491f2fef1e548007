#include "server/datasets/reload_policy.h"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "common/gis/dataset_spec_options.h"
#include "common/gis/las/las_dataset_spec.h"
#include "common/gis/ogr_dataset_spec.h"
#include "common/gis/raster_dataset_spec.h"
#include "common/gis/untrusted_ogr_spec.h"
#include "common/gis/untrusted_raster_spec.h"
#include "common/input_text.h"
#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "server/datasets/dataset_source.h"

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

Status NotInReloadDir(const std::string& requested) {
  return Status::PermissionDenied(DatasetQuoted(requested) +
                                  " is not a file in this server's reload dir");
}

// PERMISSION_DENIED for a spec that asks what a request may not ask.
Status Refused(std::string_view requested, const Status& why) {
  return Status::PermissionDenied(DatasetQuoted(requested) + ": " +
                                  why.message());
}

// Parses `kind_spec` (`requested` without max_error and max_points) as its
// kind's spec: *ogr or *raster for those kinds. InvalidArgument naming the
// spec when it does not parse, or when a text file's spec has options.
Status ParseKindSpec(const std::string& requested, const std::string& kind_spec,
                     DatasetKind kind, gis::OgrDatasetSpec* ogr,
                     gis::RasterDatasetSpec* raster) {
  switch (kind) {
    case DatasetKind::kOgr: {
      ASSIGN_OR_RETURN(*ogr, gis::ParseOgrDatasetSpec(kind_spec));
      return Status::OK();
    }
    case DatasetKind::kRaster: {
      ASSIGN_OR_RETURN(*raster, gis::ParseRasterDatasetSpec(kind_spec));
      return Status::OK();
    }
    case DatasetKind::kLas:
      // classes= and returns= only filter the file's points; the LAS
      // reader opens nothing else.
      return gis::las::ParseLasDatasetSpec(kind_spec).status();
    default: {
      std::vector<gis::SpecOption> options;
      RETURN_IF_ERROR(gis::ParseSpecOptions(kind_spec, &options));
      return options.empty()
                 ? Status::OK()
                 : gis::UnknownSpecOption(requested, options[0].name, "");
    }
  }
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

StatusOr<std::string> ReloadPolicy::Resolve(
    const std::string& requested) const {
  if (requested.empty() || requested == configured_dataset_) {
    return std::string();
  }
  if (reload_dir_.empty()) {
    return Status::PermissionDenied(
        "this server reloads only its configured dataset (start it with "
        "--reload-dir to allow others)");
  }
  return ResolveInReloadDir(requested);
}

StatusOr<std::string> ReloadPolicy::ResolveInReloadDir(
    const std::string& requested) const {
  std::string_view points;
  std::string_view wkt;
  if (SplitWktConstraintsSpec(requested, &points, &wkt)) {
    ASSIGN_OR_RETURN(const std::string points_spec,
                     ResolveInReloadDir(std::string(points)));
    const std::string wkt_file = FileInReloadDir(std::string(wkt));
    if (wkt_file.empty()) return NotInReloadDir(requested);
    return points_spec + "+" + wkt_file;
  }
  if (IsGeneratorSpec(requested)) return requested;
  return ResolveFileSpec(requested);
}

StatusOr<std::string> ReloadPolicy::ResolveFileSpec(
    const std::string& requested) const {
  // The options every kind takes (max_error, max_points) only bound what is
  // built; the rest are the kind's own, checked before the file is looked
  // at, so that a refusal says nothing about which files exist.
  gis::SimplifySpec simplify;
  std::string kind_spec;
  RETURN_IF_ERROR(gis::TakeSimplifyOptions(requested, &simplify, &kind_spec));
  const DatasetKind kind = DatasetKindOf(kind_spec);
  gis::OgrDatasetSpec ogr;
  gis::RasterDatasetSpec raster;
  RETURN_IF_ERROR(ParseKindSpec(requested, kind_spec, kind, &ogr, &raster));
  const Status refusal =
      kind == DatasetKind::kOgr      ? gis::CheckUntrustedOgrOptions(ogr)
      : kind == DatasetKind::kRaster ? gis::CheckUntrustedRasterOptions(raster)
                                     : Status::OK();
  if (!refusal.ok()) return Refused(requested, refusal);

  const gis::SpecParts parts = SplitServedSpec(requested);
  const std::string file = FileInReloadDir(std::string(parts.source));
  if (file.empty()) return NotInReloadDir(requested);
  // A file that reads others (mesh.ele reads mesh.node) is allowed only when
  // they are inside the dir too.
  for (const std::string& companion : DatasetCompanionFiles(file)) {
    if (FileInReloadDir(companion).empty()) return NotInReloadDir(requested);
  }
  // The load may open the file with one driver only: the request's, or the
  // one among those a request may use that identifies the file.
  std::string driver;
  Status identified;
  if (kind == DatasetKind::kOgr && ogr.driver.empty()) {
    identified = gis::UntrustedOgrDriver(ogr, file, &driver);
  } else if (kind == DatasetKind::kRaster && raster.driver.empty()) {
    identified = gis::UntrustedRasterDriver(raster, file, &driver);
  }
  if (!identified.ok()) return Refused(requested, identified);
  std::string spec =
      std::string(parts.prefix) + file + std::string(parts.options);
  if (!driver.empty()) {
    spec.push_back(parts.options.empty() ? '?' : '&');
    spec.append(DriverOption(driver));
  }
  return spec;
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
