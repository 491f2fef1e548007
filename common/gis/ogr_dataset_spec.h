// OgrDatasetSpec: a dataset spec that names an OGR vector source, parsed.
//
// Syntax (the options are a URL-style query; values are %-decoded, so a
// literal '&' in a where clause is %26):
//   PATH[?OPTIONS]        PATH ends in an OGR extension: .gpkg .shp
//                         .geojson .json .fgb .gml .kml .sqlite .gpx
//   ogr:SOURCE[?OPTIONS]  any OGR source (a CSV with X/Y columns, a
//                         directory of shapefiles, a /vsizip/ path, ...)
// OPTIONS, '&'-separated:
//   layer=NAME        the points layer (default: the source's only layer)
//   z=FIELD           the attribute holding the value; absent: the
//                     geometry's Z when it has one, else no values
//   where=SQL         attribute filter on the points layer (ogr2ogr -where)
//   breaklines=LAYER  LineStrings that become constrained edges
//   domain=LAYER      Polygons whose rings (exterior and interior alike)
//                     bound the domain
//   a_srs=CRS         assign this CRS (EPSG:32633, WKT or a PROJ string),
//                     ignoring the source's own (ogr2ogr -a_srs)
//   oo=NAME=VALUE     a GDAL open option (ogr2ogr -oo), repeatable, e.g.
//                     oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y for a CSV
//   driver=NAME       open the source with this GDAL driver only (its short
//                     name: GPKG, CSV, "ESRI Shapefile"; ogr2ogr -if)
//
// A spec that comes in a request (a Reload's) may use only what
// untrusted_ogr_spec.h allows; the operator's own may use all of GDAL.
//
// Thread-safety: free functions; an OgrDatasetSpec is a plain value.

#ifndef LOCATOR_COMMON_GIS_OGR_DATASET_SPEC_H_
#define LOCATOR_COMMON_GIS_OGR_DATASET_SPEC_H_

#include <string>
#include <string_view>
#include <vector>

#include "common/gis/dataset_spec_options.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis {

struct OgrDatasetSpec {
  // What GDALOpenEx opens.
  std::string source;
  std::string layer;
  std::string z_field;
  std::string where;
  std::string breaklines_layer;
  std::string domain_layer;
  std::string assigned_crs;
  // "NAME=VALUE" each, in the order given.
  std::vector<std::string> open_options;
  // The only GDAL driver that may open the source; "" for any.
  std::string driver;
};

// True when `spec` names an OGR source (the "ogr:" prefix or an OGR
// extension); other specs belong to the core's LoadDataset.
bool IsOgrDatasetSpec(std::string_view spec);

// Splits `spec` into its parts, verbatim: the "ogr:" prefix or "", the
// source, and "?OPTIONS" or "" (it does not check the options).
SpecParts SplitOgrDatasetSpec(std::string_view spec);

// Parses `spec`; InvalidArgument naming the spec for an unknown option, an
// option without '=', a repeated option or a bad %-escape.
StatusOr<OgrDatasetSpec> ParseOgrDatasetSpec(std::string_view spec);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_OGR_DATASET_SPEC_H_
