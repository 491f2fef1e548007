#include "server/datasets/dataset_source.h"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <utility>

#include "common/gis/crs_info.h"
#include "common/gis/gdal_support.h"
#include "common/gis/las/las_dataset.h"
#include "common/gis/las/las_dataset_spec.h"
#include "common/gis/ogr_dataset.h"
#include "common/gis/ogr_dataset_spec.h"
#include "common/gis/raster_dataset_spec.h"
#include "common/gis/raster_grid.h"
#include "common/input_text.h"
#include "common/status_macros.h"
#include "server/core/terrain/grid/triangulate_grid.h"
#include "server/core/terrain/points/simplify_points.h"

namespace locator {
namespace {

namespace fs = std::filesystem;

bool IsRegularFile(const std::string& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

std::string Absolute(const std::string& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  return error ? path : absolute.lexically_normal().string();
}

// `paths` made absolute when every one is a local regular file; empty
// otherwise (the dataset cannot be keyed by its files).
std::vector<std::string> LocalFiles(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    if (!IsRegularFile(path)) return {};
    files.push_back(Absolute(path));
  }
  return files;
}

// The files a text or generator spec reads: its file and that file's
// companions (a .ele's .node), and for POINTS+PATH.wkt the WKT file besides
// the points spec's own.
std::vector<std::string> TextSpecFiles(std::string_view spec) {
  std::string_view points, wkt;
  if (SplitWktConstraintsSpec(spec, &points, &wkt)) {
    std::vector<std::string> files = TextSpecFiles(points);
    files.emplace_back(wkt);
    return files;
  }
  if (IsGeneratorSpec(spec)) return {};
  std::vector<std::string> files = {std::string(spec)};
  for (std::string& companion : DatasetCompanionFiles(std::string(spec))) {
    files.push_back(std::move(companion));
  }
  return files;
}

TinOptions TinOptionsFor(const gis::SimplifySpec& simplify,
                         const ServedLoadOptions& options) {
  TinOptions tin;
  tin.max_error = simplify.max_error;
  tin.max_points = simplify.max_points;
  tin.threads = options.threads;
  tin.progress = options.progress;
  tin.progress_interval_s = options.progress_interval_s;
  return tin;
}

// The simplifier's errors do not know the spec: an InvalidArgument gets it
// in front.
Status Prefixed(const std::string& spec, const Status& status) {
  if (status.code() != Status::Code::kInvalidArgument) return status;
  return Status::InvalidArgument(spec + ": " + status.message());
}

// The raster `spec` names, triangulated within `simplify`.
Status LoadRaster(const std::string& spec, const gis::SimplifySpec& simplify,
                  const ServedLoadOptions& options, ServedDataset* out) {
  ElevationGrid grid;
  std::vector<std::string> read;
  if (Status s = gis::ReadElevationGrid(spec, options.limits, &grid, &read);
      !s.ok()) {
    return s;
  }
  SimplificationStats stats;
  if (Status s = TriangulateGrid(grid, TinOptionsFor(simplify, options),
                                 &out->dataset, &stats);
      !s.ok()) {
    return Prefixed(grid.source, s);
  }
  out->simplification = stats;
  out->files = LocalFiles(read);
  if (out->files.empty()) return Status::OK();
  const StatusOr<gis::RasterDatasetSpec> parsed =
      gis::ParseRasterDatasetSpec(spec);
  if (!parsed.ok()) return Status::OK();
  // GDAL reads these side-cars when they exist (nodata, scale and CRS in an
  // .aux.xml, a mask, a .prj, a world file): one that appears later
  // changes the dataset.
  const fs::path source = Absolute(parsed->source);
  fs::path stem = source;
  stem.replace_extension();
  for (const fs::path& side_car :
       {fs::path(source.string() + ".aux.xml"),
        fs::path(source.string() + ".msk"), fs::path(stem.string() + ".prj"),
        fs::path(stem.string() + ".wld"), fs::path(stem.string() + ".tfw")}) {
    if (std::find(out->files.begin(), out->files.end(), side_car.string()) ==
            out->files.end() &&
        !fs::exists(side_car)) {
      out->absent_files.push_back(side_car.string());
    }
  }
  return Status::OK();
}

// The files an OGR spec's source reads, when they are local files.
std::vector<std::string> OgrFiles(const std::string& spec) {
  const StatusOr<gis::OgrDatasetSpec> parsed = gis::ParseOgrDatasetSpec(spec);
  std::vector<std::string> files;
  if (!parsed.ok() || !gis::VectorFileList(parsed->source, parsed->open_options,
                                           parsed->driver, &files)
                           .ok()) {
    return {};
  }
  return LocalFiles(files);
}

// Loads the points of `spec` (a kind other than a raster).
Status LoadPoints(const std::string& whole_spec, const std::string& spec,
                  DatasetKind kind, const DatasetLimits& limits,
                  ServedDataset* out) {
  switch (kind) {
    case DatasetKind::kLas: {
      RETURN_IF_ERROR(gis::las::LoadLasDataset(spec, &out->dataset, limits));
      const StatusOr<gis::las::LasDatasetSpec> parsed =
          gis::las::ParseLasDatasetSpec(spec);
      if (parsed.ok()) out->files = LocalFiles({parsed->path});
      return Status::OK();
    }
    case DatasetKind::kOgr:
      if (Status s = gis::LoadOgrDataset(spec, &out->dataset, limits);
          !s.ok()) {
        return s;
      }
      out->files = OgrFiles(spec);
      return Status::OK();
    default: {
      // Text files and generators take no options of their own.
      std::vector<gis::SpecOption> options;
      RETURN_IF_ERROR(gis::ParseSpecOptions(spec, &options));
      if (!options.empty()) {
        return gis::UnknownSpecOption(whole_spec, options[0].name, "");
      }
      ASSIGN_OR_RETURN(out->dataset, LoadDataset(spec, limits));
      out->files = LocalFiles(TextSpecFiles(spec));
      return Status::OK();
    }
  }
}

// Replaces out->dataset with its TIN within `simplify`.
Status SimplifyLoaded(const std::string& spec,
                      const gis::SimplifySpec& simplify,
                      const ServedLoadOptions& options, ServedDataset* out) {
  Dataset tin;
  SimplificationStats stats;
  if (Status s = SimplifyPoints(out->dataset, TinOptionsFor(simplify, options),
                                &tin, &stats);
      !s.ok()) {
    return Prefixed(spec, s);
  }
  out->dataset = std::move(tin);
  out->simplification = stats;
  return Status::OK();
}

// Stats and request transforms rely on PROJ knowing the dataset's CRS.
Status CheckCrs(const std::string& spec, const std::string& crs) {
  if (crs.empty()) return Status::OK();
  if (const StatusOr<gis::CrsInfo> info = gis::DescribeCrsMemoized(crs);
      !info.ok()) {
    return Status::InvalidArgument(spec + ": " + info.status().message());
  }
  return Status::OK();
}

}  // namespace

DatasetKind DatasetKindOf(std::string_view spec) {
  if (spec.starts_with("ogr:")) return DatasetKind::kOgr;
  if (spec.starts_with("raster:")) return DatasetKind::kRaster;
  if (spec.starts_with("las:")) return DatasetKind::kLas;
  if (IsGeneratorSpec(spec)) return DatasetKind::kGenerator;
  if (gis::las::IsLasDatasetSpec(spec)) return DatasetKind::kLas;
  if (gis::IsRasterDatasetSpec(spec)) return DatasetKind::kRaster;
  if (gis::IsOgrDatasetSpec(spec)) return DatasetKind::kOgr;
  return DatasetKind::kText;
}

gis::SpecParts SplitServedSpec(std::string_view spec) {
  switch (DatasetKindOf(spec)) {
    case DatasetKind::kOgr:
      return gis::SplitOgrDatasetSpec(spec);
    case DatasetKind::kRaster:
      return gis::SplitRasterDatasetSpec(spec);
    case DatasetKind::kLas:
      return gis::las::SplitLasDatasetSpec(spec);
    default:
      return gis::SplitSpec(spec);
  }
}

Status LoadServedDataset(const std::string& spec,
                         const ServedLoadOptions& options, ServedDataset* out) {
  if (spec.find('?') != std::string::npos && IsRegularFile(spec)) {
    return Status::InvalidArgument(
        QuotedInput(spec) +
        " names a file, but a dataset spec's options begin at its first "
        "'?': link or rename the file to a name without '?'");
  }
  gis::SimplifySpec simplify;
  std::string kind_spec;
  if (Status s = gis::TakeSimplifyOptions(spec, &simplify, &kind_spec);
      !s.ok()) {
    return s;
  }
  const DatasetKind kind = DatasetKindOf(kind_spec);
  ServedDataset served;
  Status status =
      kind == DatasetKind::kRaster
          ? LoadRaster(kind_spec, simplify, options, &served)
          : LoadPoints(spec, kind_spec, kind, options.limits, &served);
  if (status.ok() && kind != DatasetKind::kRaster && simplify.requested) {
    status = SimplifyLoaded(spec, simplify, options, &served);
  }
  if (status.ok()) status = CheckCrs(spec, served.dataset.crs);
  if (!status.ok()) return status;
  served.dataset.source = spec;
  *out = std::move(served);
  return Status::OK();
}

}  // namespace locator
