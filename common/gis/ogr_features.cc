#include "common/gis/ogr_features.h"

#include <cmath>

#include "common/gis/gdal_support.h"
#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {

std::string FeatureLocation::Prefix() const {
  return source + ": layer " + QuotedInput(layer);
}

std::string FeatureLocation::Feature(GIntBig fid) const {
  return Prefix() + ": feature " + std::to_string(fid);
}

Status FeatureLocation::Bad(GIntBig fid, const std::string& what) const {
  return Status::InvalidArgument(Feature(fid) + ": " + what);
}

Status ForEachFeature(const FeatureLocation& where, OGRLayer& layer,
                      const std::function<Status(const OGRFeature&)>& add) {
  GdalErrorTrap trap;
  layer.ResetReading();
  GIntBig previous_fid = OGRNullFID;
  for (uint64_t number = 1;; ++number) {
    const OGRFeatureUniquePtr feature(layer.GetNextFeature());
    if (std::string failure = trap.TakeFailure(); !failure.empty()) {
      if (feature != nullptr) return where.Bad(feature->GetFID(), failure);
      return Status::InvalidArgument(
          where.Prefix() + ": feature number " + std::to_string(number) +
          (previous_fid == OGRNullFID
               ? std::string(" (the first)")
               : " (the one after FID " + std::to_string(previous_fid) + ")") +
          ": " + failure);
    }
    if (feature == nullptr) return Status::OK();
    previous_fid = feature->GetFID();
    RETURN_IF_ERROR(add(*feature));
  }
}

Status CheckFinite(const FeatureLocation& where, GIntBig fid,
                   const OGRPoint& p) {
  if (std::isfinite(p.getX()) && std::isfinite(p.getY()) &&
      (!p.Is3D() || std::isfinite(p.getZ()))) {
    return Status::OK();
  }
  return where.Bad(fid, "non-finite coordinate");
}

}  // namespace locator::gis
