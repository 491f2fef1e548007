// What an OGR dataset spec that comes in a request (a Reload's) may make
// GDAL do: read the file the spec names, and nothing else. The operator's
// own specs (--dataset) are not checked here; they may use all of GDAL.
//
//   - The source is read by one of a few drivers (GPKG, ESRI Shapefile,
//     GeoJSON, GeoJSONSeq, FlatGeobuf, CSV, KML, GPX): formats whose reader
//     opens the named file (and its own sidecars: a .shp's .shx, .dbf and
//     .prj, a .csv's .csvt and .prj) but no other file its content could
//     name (VRT; GML's schemas and .gfs; SQLite with SpatiaLite's or OGR's
//     virtual tables) and no network. The driver is driver= when given,
//     else the one of these GDAL identifies the file as.
//   - oo= is one of the open options of those drivers that only change how
//     the file is parsed. None that runs SQL (GPKG's PRELUDE_STATEMENTS),
//     names, writes or downloads a file, or reaches the network (GeoJSON's
//     FEATURE_SERVER_PAGING).
//   - where= is a plain comparison of fields and literals
//     (CheckPlainWhereClause): no SQL function, no sub-select.
//   - a_srs= passes the request CRS policy (CheckRequestCrs): no file
//     outside PROJ's data directories.
//   - layer=, z=, breaklines= and domain= only name layers and fields of
//     the file.
//
// Thread-safety: free functions; may run on any thread.

#ifndef LOCATOR_COMMON_GIS_UNTRUSTED_OGR_SPEC_H_
#define LOCATOR_COMMON_GIS_UNTRUSTED_OGR_SPEC_H_

#include <string>

#include "common/gis/ogr_dataset_spec.h"
#include "locator/status.h"

namespace locator::gis {

// OK when a request may use every option of `spec`; else InvalidArgument
// naming the first option it may not use and why.
Status CheckUntrustedOgrOptions(const OgrDatasetSpec& spec);

// The driver that is to read `path` (the spec's source, resolved) for a
// request's `spec`: spec.driver when it is one of the drivers above, else
// the one GDAL identifies `path` as. InvalidArgument naming the drivers when
// there is none.
Status UntrustedOgrDriver(const OgrDatasetSpec& spec, const std::string& path,
                          std::string* driver);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_UNTRUSTED_OGR_SPEC_H_
