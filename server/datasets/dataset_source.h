// LoadServedDataset: the one place locatord turns a --dataset spec (or a
// Reload request's spec) into the dataset it serves, at startup and on every
// reload.
//
// A spec is SOURCE[?OPTIONS], the options beginning at its first '?'
// (common/gis/dataset_spec_options.h). Its kind, decided in this order:
//   POINTS+PATH.wkt       text: points constrained by a WKT file (core)
//   uniform:, clusters:   generator (core)
//   ogr:SOURCE            OGR vector source (locator_gis)
//   raster:SOURCE         raster DEM (locator_gis)
//   las:PATH              LAS point cloud (locator_gis)
//   PATH by extension     .las .laz: LAS; .tif .vrt .asc ...: raster
//                         (raster_dataset_spec.h); .gpkg .shp ...: OGR
//   any other PATH        text: CSV/XYZ, .node, .poly, .ele, .off (core)
// A raster is always served as the TIN TriangulateGrid builds of it within
// max_error (0 by default: every valid pixel); a point dataset given
// max_error or max_points is thinned by SimplifyPoints. Either way the
// certificate comes with the dataset. A source's CRS is checked with PROJ.
// A spec whose whole text (options included) names an existing file is
// refused, saying that options begin at the first '?'.
//
// Thread-safety: free functions; may run on any thread.

#ifndef LOCATOR_SERVER_DATASET_SOURCE_H_
#define LOCATOR_SERVER_DATASET_SOURCE_H_

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/gis/dataset_spec_options.h"
#include "locator/dataset_sources.h"
#include "locator/status.h"
#include "server/core/terrain/tin_options.h"

namespace locator {

enum class DatasetKind { kText, kGenerator, kOgr, kRaster, kLas };

// The kind of `spec` (see above).
DatasetKind DatasetKindOf(std::string_view spec);

// Splits `spec` into its kind's prefix ("ogr:", "raster:", "las:" or ""),
// its source (the file a file kind reads, a generator's spec) and
// "?OPTIONS" or "": what the reload policy resolves. Not for
// POINTS+PATH.wkt (see SplitWktConstraintsSpec).
gis::SpecParts SplitServedSpec(std::string_view spec);

struct ServedLoadOptions {
  // Points (or pixels) a dataset may read.
  DatasetLimits limits;
  // Threads a simplification may use.
  unsigned threads = 1;
  // Called while a simplification runs, at least every
  // progress_interval_s seconds (TinOptions::progress).
  std::function<void(const TinProgress&)> progress;
  double progress_interval_s = 5;
};

// What LoadServedDataset made of a spec.
struct ServedDataset {
  // What the engine is built from: for a simplified dataset the TIN, its
  // mesh as constraints.triangles. source is the whole spec.
  Dataset dataset;
  // The certificate of a simplified dataset; unset otherwise.
  std::optional<SimplificationStats> simplification;
  // The files it was read from (absolute paths, side-cars included) when
  // every one is a local file, so that the mesh cache can key the dataset
  // by their identity; empty otherwise (generators, /vsi sources).
  std::vector<std::string> files;
  // Files whose later appearance would change the dataset (a raster's
  // side-cars that do not exist yet: .aux.xml, .msk, .prj, .wld, .tfw),
  // absolute.
  std::vector<std::string> absent_files;
};

// Loads the dataset `spec` names into *out (see above). Errors are the
// loaders' and the simplifier's (they name the file and line, or the
// source, layer, feature, band or pixel), InvalidArgument naming the spec
// for an option its kind does not take, or InvalidArgument when PROJ does
// not understand the source's CRS.
Status LoadServedDataset(const std::string& spec,
                         const ServedLoadOptions& options, ServedDataset* out);

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASET_SOURCE_H_
