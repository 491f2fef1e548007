// ReadConstraintLayer: the breaklines or the domain rings of a dataset,
// read from an OGR layer for LoadOgrDataset (ogr_dataset.h says what
// becomes what).
//
// Thread-safety: a free function; GDAL layers are not shared.

#ifndef LOCATOR_COMMON_GIS_OGR_CONSTRAINTS_H_
#define LOCATOR_COMMON_GIS_OGR_CONSTRAINTS_H_

#include <ogrsf_frmts.h>

#include "common/gis/ogr_features.h"
#include "locator/dataset.h"
#include "locator/status.h"

namespace locator::gis {

// Appends every feature of `layer` to out->breaklines (LineStrings and
// MultiLineStrings; their Z too when `keep_z`) or, when `domain`, to
// out->rings (every ring of Polygons and MultiPolygons). InvalidArgument
// naming the feature for another geometry, an empty or non-finite one, a
// breakline of fewer than 2 points or a ring of fewer than 3, and for an
// empty layer; ForEachFeature's errors.
Status ReadConstraintLayer(const FeatureLocation& where, OGRLayer& layer,
                           bool domain, bool keep_z, DatasetConstraints* out);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_OGR_CONSTRAINTS_H_
