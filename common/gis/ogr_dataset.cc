#include "common/gis/ogr_dataset.h"

#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdlib>
#include <utility>

#include "common/gis/gdal_support.h"
#include "common/gis/ogr_constraints.h"
#include "common/gis/ogr_features.h"
#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

Status OpenSource(const OgrDatasetSpec& spec, GDALDatasetUniquePtr* out) {
  RegisterGdalDrivers();
  CPLStringList open_options;
  for (const std::string& option : spec.open_options) {
    open_options.AddString(option.c_str());
  }
  const char* const only_driver[] = {spec.driver.c_str(), nullptr};
  if (!spec.driver.empty() &&
      GDALGetDriverByName(spec.driver.c_str()) == nullptr) {
    return Status::InvalidArgument(spec.source + ": no GDAL driver " +
                                   QuotedInput(spec.driver) + " (driver=)");
  }
  CPLErrorReset();
  out->reset(GDALDataset::Open(spec.source.c_str(),
                               GDAL_OF_VECTOR | GDAL_OF_READONLY,
                               spec.driver.empty() ? nullptr : only_driver,
                               open_options.List(), nullptr));
  if (*out != nullptr) return Status::OK();
  VSIStatBufL stat;
  if (VSIStatL(spec.source.c_str(), &stat) != 0) {
    return Status::NotFound(spec.source + ": no such file or directory");
  }
  return Status::InvalidArgument(
      spec.source + ": not a readable OGR vector source" +
      (spec.driver.empty() ? "" : " for driver " + QuotedInput(spec.driver)) +
      ": " + LastGdalError());
}

std::string LayerNames(GDALDataset& source) {
  std::string names;
  for (OGRLayer* layer : source.GetLayers()) {
    names += (names.empty() ? "" : ", ") + QuotedInput(layer->GetName());
  }
  return names.empty() ? "none" : names;
}

// The layer `name` names, or the source's only layer when `name` is empty.
Status FindLayer(GDALDataset& source, const std::string& source_name,
                 const std::string& name, OGRLayer** out) {
  if (name.empty()) {
    if (source.GetLayerCount() != 1) {
      return Status::InvalidArgument(
          source_name + ": " + std::to_string(source.GetLayerCount()) +
          " layers (" + LayerNames(source) + "); name one with ?layer=");
    }
    *out = source.GetLayer(0);
    return Status::OK();
  }
  *out = source.GetLayerByName(name.c_str());
  if (*out == nullptr) {
    return Status::NotFound(source_name + ": no layer " + QuotedInput(name) +
                            " (layers: " + LayerNames(source) + ")");
  }
  return Status::OK();
}

// Reads the value of field `index` of `feature`: a number, or a text that
// is one.
Status FieldValue(const FeatureLocation& where, const OGRFeature& feature,
                  int index, double* value) {
  const std::string name = feature.GetFieldDefnRef(index)->GetNameRef();
  if (!feature.IsFieldSetAndNotNull(index)) {
    return where.Bad(feature.GetFID(),
                     "field " + QuotedInput(name) + " is null");
  }
  const char* text = feature.GetFieldAsString(index);
  char* end = nullptr;
  *value = CPLStrtod(text, &end);
  if (end == text || *end != '\0') {
    return where.Bad(feature.GetFID(), "field " + QuotedInput(name) + " is " +
                                           QuotedInput(text) +
                                           ", not a number");
  }
  if (!std::isfinite(*value)) {
    return where.Bad(feature.GetFID(),
                     "field " + QuotedInput(name) + " is non-finite");
  }
  return Status::OK();
}

// Reads the points layer into out->points and out->values.
class PointReader {
 public:
  PointReader(FeatureLocation where, const DatasetLimits& limits, Dataset* out)
      : where_(std::move(where)), limits_(limits), out_(out) {}

  Status Read(OGRLayer& layer, const OgrDatasetSpec& spec) {
    if (!spec.where.empty()) {
      CPLErrorReset();
      if (layer.SetAttributeFilter(spec.where.c_str()) != OGRERR_NONE) {
        return Status::InvalidArgument(where_.Prefix() + ": bad where " +
                                       QuotedInput(spec.where) + ": " +
                                       LastGdalError());
      }
    }
    if (!spec.z_field.empty()) {
      z_index_ = layer.GetLayerDefn()->GetFieldIndex(spec.z_field.c_str());
      if (z_index_ < 0) {
        return Status::NotFound(where_.Prefix() + ": no field " +
                                QuotedInput(spec.z_field));
      }
    }
    geometry_z_ = z_index_ < 0 && OGR_GT_HasZ(layer.GetGeomType());
    RETURN_IF_ERROR(ForEachFeature(
        where_, layer,
        [this](const OGRFeature& feature) { return AddFeature(feature); }));
    if (out_->points.empty()) {
      return Status::InvalidArgument(
          where_.Prefix() + " has no features" +
          (spec.where.empty() ? ""
                              : " matching where " + QuotedInput(spec.where)));
    }
    if (z_index_ < 0 && !geometry_z_) out_->values.clear();
    return Status::OK();
  }

 private:
  Status AddFeature(const OGRFeature& feature) {
    const GIntBig fid = feature.GetFID();
    const OGRGeometry* geometry = feature.GetGeometryRef();
    if (geometry == nullptr) return where_.Bad(fid, "no geometry");
    if (geometry->IsEmpty()) return where_.Bad(fid, "empty geometry");
    double field_value = 0;
    if (z_index_ >= 0) {
      RETURN_IF_ERROR(FieldValue(where_, feature, z_index_, &field_value));
    }
    switch (wkbFlatten(geometry->getGeometryType())) {
      case wkbPoint:
        return AddPoint(fid, *geometry->toPoint(), field_value);
      case wkbMultiPoint:
        for (const OGRPoint* point : *geometry->toMultiPoint()) {
          RETURN_IF_ERROR(AddPoint(fid, *point, field_value));
        }
        return Status::OK();
      default:
        return where_.Bad(fid, std::string("a ") + geometry->getGeometryName() +
                                   " where points are expected (Point, "
                                   "MultiPoint)");
    }
  }

  Status AddPoint(GIntBig fid, const OGRPoint& point, double field_value) {
    if (point.IsEmpty()) return where_.Bad(fid, "empty point");
    RETURN_IF_ERROR(CheckFinite(where_, fid, point));
    if (geometry_z_ && !point.Is3D()) {
      return where_.Bad(fid, "a point without Z in a layer with Z");
    }
    if (out_->points.size() >= limits_.max_points) {
      return Status::ResourceExhausted(where_.Prefix() + ": more than " +
                                       std::to_string(limits_.max_points) +
                                       " points (max_points limit)");
    }
    out_->points.push_back(Point2{point.getX(), point.getY()});
    out_->values.push_back(geometry_z_ ? point.getZ() : field_value);
    return Status::OK();
  }

  const FeatureLocation where_;
  const DatasetLimits& limits_;
  Dataset* const out_;
  int z_index_ = -1;
  bool geometry_z_ = false;
};

// The dataset's CRS: a_srs, else the one the layers agree on, else none.
Status ResolveCrs(const OgrDatasetSpec& spec,
                  const std::vector<OGRLayer*>& layers, std::string* wkt) {
  if (!spec.assigned_crs.empty()) {
    OGRSpatialReference srs;
    const char* const options[] = {"ALLOW_NETWORK_ACCESS=NO",
                                   "ALLOW_FILE_ACCESS=NO", nullptr};
    CPLErrorReset();
    if (srs.SetFromUserInput(spec.assigned_crs.c_str(), options) !=
        OGRERR_NONE) {
      return Status::InvalidArgument(spec.source + ": unknown CRS " +
                                     QuotedInput(spec.assigned_crs) +
                                     " (a_srs): " + LastGdalError());
    }
    *wkt = SpatialRefToWkt(srs);
    return Status::OK();
  }
  OGRLayer* first = nullptr;
  for (OGRLayer* layer : layers) {
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    if (srs == nullptr) continue;
    if (first == nullptr) {
      first = layer;
      *wkt = SpatialRefToWkt(*srs);
    } else if (!srs->IsSame(first->GetSpatialRef())) {
      return Status::InvalidArgument(
          spec.source + ": layer " + QuotedInput(layer->GetName()) +
          " is in CRS " + QuotedInput(srs->GetName()) + " but layer " +
          QuotedInput(first->GetName()) + " is in " +
          QuotedInput(first->GetSpatialRef()->GetName()) +
          " (a_srs= assigns one CRS)");
    }
  }
  return Status::OK();
}

}  // namespace

Status LoadOgrDataset(const std::string& spec_text, Dataset* out,
                      const DatasetLimits& limits) {
  ASSIGN_OR_RETURN(const OgrDatasetSpec spec, ParseOgrDatasetSpec(spec_text));
  // GDAL reports through its error state, not stderr.
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  GDALDatasetUniquePtr source;
  RETURN_IF_ERROR(OpenSource(spec, &source));

  Dataset dataset;
  dataset.source = spec_text;
  OGRLayer* points = nullptr;
  RETURN_IF_ERROR(FindLayer(*source, spec.source, spec.layer, &points));
  std::vector<OGRLayer*> layers = {points};
  RETURN_IF_ERROR(PointReader(FeatureLocation{spec.source, points->GetName()},
                              limits, &dataset)
                      .Read(*points, spec));
  for (const bool domain : {false, true}) {
    const std::string& name =
        domain ? spec.domain_layer : spec.breaklines_layer;
    if (name.empty()) continue;
    OGRLayer* layer = nullptr;
    RETURN_IF_ERROR(FindLayer(*source, spec.source, name, &layer));
    layers.push_back(layer);
    RETURN_IF_ERROR(ReadConstraintLayer(FeatureLocation{spec.source, name},
                                        *layer, domain, dataset.has_values(),
                                        &dataset.constraints));
  }
  RETURN_IF_ERROR(ResolveCrs(spec, layers, &dataset.crs));
  *out = std::move(dataset);
  return Status::OK();
}

}  // namespace locator::gis
