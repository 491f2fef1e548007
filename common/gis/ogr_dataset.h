// LoadOgrDataset: reads a core Dataset (points, values, breaklines, domain
// rings and the CRS as WKT) from any OGR vector source, through GDAL.
//
// The spec syntax is OgrDatasetSpec's (ogr_dataset_spec.h). What becomes
// what:
//   points layer      Point, PointZ and MultiPoint(Z) features are points;
//                     values from the `z` field, else the geometry's Z when
//                     the layer has Z, else none.
//   breaklines layer  LineString and MultiLineString parts; their Z, when
//                     they have one and the dataset has values, is kept.
//   domain layer      every ring (exterior and interior) of Polygons and
//                     MultiPolygons; nesting depth decides what is inside.
// The CRS is a_srs when given, else the layers' own (which must agree),
// else none.
//
// Errors name the source and the layer, and the feature by FID where one
// is to blame: NotFound for a missing file, layer or field; InvalidArgument
// for an unreadable source, a bad where clause, a geometry of the wrong
// kind, an empty or non-finite geometry, a null or non-numeric z, layers in
// different CRSs, an unknown a_srs and an empty layer, and for any failure
// GDAL reports while it reads a feature (a corrupt file: GDAL would end the
// layer there, and the dataset would silently lack the rest), which names
// the feature by FID or, when GDAL could not read it, by its number in the
// layer; ResourceExhausted past DatasetLimits::max_points.
//
// Thread-safety: may be called from several threads at once (GDAL dataset
// handles are not shared; GDAL's error state is per thread).

#ifndef LOCATOR_COMMON_GIS_OGR_DATASET_H_
#define LOCATOR_COMMON_GIS_OGR_DATASET_H_

#include <string>

#include "common/gis/ogr_dataset_spec.h"
#include "locator/dataset.h"
#include "locator/status.h"

namespace locator::gis {

// Loads the OGR source `spec` names (see IsOgrDatasetSpec) into *out;
// out->source is `spec`.
Status LoadOgrDataset(const std::string& spec, Dataset* out,
                      const DatasetLimits& limits = DatasetLimits());

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_OGR_DATASET_H_
