// Reading an OGR layer's features for LoadOgrDataset: the names a message
// gives the source, the layer and the feature, and ForEachFeature, which
// fails on any GDAL failure while the layer is read instead of serving what
// came before it.
//
// Thread-safety: free functions and plain values; ForEachFeature pushes a
// GDAL error handler for the calling thread only.

#ifndef LOCATOR_COMMON_GIS_OGR_FEATURES_H_
#define LOCATOR_COMMON_GIS_OGR_FEATURES_H_

#include <ogr_feature.h>
#include <ogrsf_frmts.h>

#include <functional>
#include <string>

#include "locator/status.h"

namespace locator::gis {

// Names the source, the layer and (optionally) the feature in messages.
struct FeatureLocation {
  std::string source;
  std::string layer;

  // "SOURCE: layer 'LAYER'".
  std::string Prefix() const;
  // "SOURCE: layer 'LAYER': feature FID".
  std::string Feature(GIntBig fid) const;
  // InvalidArgument "SOURCE: layer 'LAYER': feature FID: WHAT".
  Status Bad(GIntBig fid, const std::string& what) const;
};

// Calls `add` for every feature of `layer` from its start, in order, until
// one fails. InvalidArgument naming the feature (by FID when GDAL returned
// it, else by its number in the layer and the FID before it) when GDAL
// reports a failure while reading it, such as a corrupt page of a
// GeoPackage, after which GDAL would end the layer early.
Status ForEachFeature(const FeatureLocation& where, OGRLayer& layer,
                      const std::function<Status(const OGRFeature&)>& add);

// InvalidArgument naming the feature when `p` has a non-finite coordinate.
Status CheckFinite(const FeatureLocation& where, GIntBig fid,
                   const OGRPoint& p);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_OGR_FEATURES_H_
