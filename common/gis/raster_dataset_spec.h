// RasterDatasetSpec: a dataset spec that names a raster DEM, parsed.
//
// Syntax (dataset_spec_options.h has the option rules and the options every
// kind takes: max_error, 0 by default for a raster, and max_points):
//   PATH[?OPTIONS]          PATH ends in a raster extension (any case):
//                           .tif .tiff .vrt .asc .img .dem .hgt .bil .flt
//                           .grd
//   raster:SOURCE[?OPTIONS] any raster GDAL opens (another extension, a
//                           /vsizip/ path, ...)
// OPTIONS, '&'-separated:
//   band=N     the band of elevations, from 1 (default 1)
//   a_srs=CRS  assign this CRS (EPSG:32633, WKT or a PROJ string), ignoring
//              the raster's own (gdal_translate -a_srs)
//   driver=D   open the source with this GDAL driver only (its short name:
//              GTiff, AAIGrid; gdal_translate -if)
//
// A spec that comes in a request (a Reload's) may use only what
// untrusted_raster_spec.h allows; the operator's own may use all of GDAL.
//
// Thread-safety: free functions; a RasterDatasetSpec is a plain value.

#ifndef LOCATOR_COMMON_GIS_RASTER_DATASET_SPEC_H_
#define LOCATOR_COMMON_GIS_RASTER_DATASET_SPEC_H_

#include <string>
#include <string_view>

#include "common/gis/dataset_spec_options.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis {

struct RasterDatasetSpec {
  // What GDALOpenEx opens.
  std::string source;
  int band = 1;
  std::string assigned_crs;
  // The only GDAL driver that may open the source; "" for any.
  std::string driver;
};

// True when `spec` names a raster: the "raster:" prefix or a raster
// extension.
bool IsRasterDatasetSpec(std::string_view spec);

// Splits `spec` into its parts, verbatim: "raster:" or "", the source, and
// "?OPTIONS" or "".
SpecParts SplitRasterDatasetSpec(std::string_view spec);

// Parses `spec`; InvalidArgument naming the spec and the option for an
// unknown or repeated option, a band that is not a positive integer, an
// empty a_srs or driver, or no source.
StatusOr<RasterDatasetSpec> ParseRasterDatasetSpec(std::string_view spec);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_RASTER_DATASET_SPEC_H_
