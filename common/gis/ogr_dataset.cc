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

namespace locator::gis {
namespace {

// Names the source, the layer and (optionally) the feature in messages.
struct Where {
  std::string source;
  std::string layer;

  std::string Prefix() const { return source + ": layer '" + layer + "'"; }
  std::string Feature(GIntBig fid) const {
    return Prefix() + ": feature " + std::to_string(fid);
  }
  Status Bad(GIntBig fid, const std::string& what) const {
    return Status::InvalidArgument(Feature(fid) + ": " + what);
  }
};

Status OpenSource(const OgrDatasetSpec& spec, GDALDatasetUniquePtr* out) {
  RegisterGdalDrivers();
  CPLStringList open_options;
  for (const std::string& option : spec.open_options) {
    open_options.AddString(option.c_str());
  }
  CPLErrorReset();
  out->reset(GDALDataset::Open(spec.source.c_str(),
                               GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr,
                               open_options.List(), nullptr));
  if (*out != nullptr) return Status::OK();
  VSIStatBufL stat;
  if (VSIStatL(spec.source.c_str(), &stat) != 0) {
    return Status::NotFound(spec.source + ": no such file or directory");
  }
  return Status::InvalidArgument(
      spec.source + ": not a readable OGR vector source: " + LastGdalError());
}

std::string LayerNames(GDALDataset& source) {
  std::string names;
  for (OGRLayer* layer : source.GetLayers()) {
    names +=
        (names.empty() ? "'" : ", '") + std::string(layer->GetName()) + "'";
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
    return Status::NotFound(source_name + ": no layer '" + name +
                            "' (layers: " + LayerNames(source) + ")");
  }
  return Status::OK();
}

Status CheckFinite(const Where& where, GIntBig fid, const OGRPoint& p) {
  if (std::isfinite(p.getX()) && std::isfinite(p.getY()) &&
      (!p.Is3D() || std::isfinite(p.getZ()))) {
    return Status::OK();
  }
  return where.Bad(fid, "non-finite coordinate");
}

// Reads the value of field `index` of `feature`: a number, or a text that
// is one.
Status FieldValue(const Where& where, const OGRFeature& feature, int index,
                  double* value) {
  const std::string name = feature.GetFieldDefnRef(index)->GetNameRef();
  if (!feature.IsFieldSetAndNotNull(index)) {
    return where.Bad(feature.GetFID(), "field '" + name + "' is null");
  }
  const char* text = feature.GetFieldAsString(index);
  char* end = nullptr;
  *value = CPLStrtod(text, &end);
  if (end == text || *end != '\0') {
    return where.Bad(feature.GetFID(),
                     "field '" + name + "' is '" + text + "', not a number");
  }
  if (!std::isfinite(*value)) {
    return where.Bad(feature.GetFID(), "field '" + name + "' is non-finite");
  }
  return Status::OK();
}

// Reads the points layer into out->points and out->values.
class PointReader {
 public:
  PointReader(Where where, const DatasetLimits& limits, Dataset* out)
      : where_(std::move(where)), limits_(limits), out_(out) {}

  Status Read(OGRLayer& layer, const OgrDatasetSpec& spec) {
    if (!spec.where.empty()) {
      CPLErrorReset();
      if (layer.SetAttributeFilter(spec.where.c_str()) != OGRERR_NONE) {
        return Status::InvalidArgument(where_.Prefix() + ": bad where '" +
                                       spec.where + "': " + LastGdalError());
      }
    }
    if (!spec.z_field.empty()) {
      z_index_ = layer.GetLayerDefn()->GetFieldIndex(spec.z_field.c_str());
      if (z_index_ < 0) {
        return Status::NotFound(where_.Prefix() + ": no field '" +
                                spec.z_field + "'");
      }
    }
    geometry_z_ = z_index_ < 0 && OGR_GT_HasZ(layer.GetGeomType());
    for (const OGRFeatureUniquePtr& feature : layer) {
      if (Status status = AddFeature(*feature); !status.ok()) return status;
    }
    if (out_->points.empty()) {
      return Status::InvalidArgument(
          where_.Prefix() + " has no features" +
          (spec.where.empty() ? "" : " matching where '" + spec.where + "'"));
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
      if (Status status = FieldValue(where_, feature, z_index_, &field_value);
          !status.ok()) {
        return status;
      }
    }
    switch (wkbFlatten(geometry->getGeometryType())) {
      case wkbPoint:
        return AddPoint(fid, *geometry->toPoint(), field_value);
      case wkbMultiPoint:
        for (const OGRPoint* point : *geometry->toMultiPoint()) {
          if (Status status = AddPoint(fid, *point, field_value);
              !status.ok()) {
            return status;
          }
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
    if (Status status = CheckFinite(where_, fid, point); !status.ok()) {
      return status;
    }
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

  const Where where_;
  const DatasetLimits& limits_;
  Dataset* const out_;
  int z_index_ = -1;
  bool geometry_z_ = false;
};

// Appends `curve`'s points to *line; Z values too when `keep_z`.
Status AppendCurve(const Where& where, GIntBig fid, const OGRSimpleCurve& curve,
                   bool keep_z, Polyline* line) {
  for (const OGRPoint& point : curve) {
    if (Status status = CheckFinite(where, fid, point); !status.ok()) {
      return status;
    }
    line->points.push_back(Point2{point.getX(), point.getY()});
    if (keep_z) line->values.push_back(point.getZ());
  }
  return Status::OK();
}

// The polylines of one breaklines feature.
Status ReadBreakline(const Where& where, GIntBig fid, const OGRGeometry& g,
                     bool keep_z, std::vector<Polyline>* out) {
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbLineString: {
      Polyline line;
      if (Status status = AppendCurve(where, fid, *g.toLineString(),
                                      keep_z && g.Is3D(), &line);
          !status.ok()) {
        return status;
      }
      if (line.points.size() < 2) {
        return where.Bad(fid, "a breakline with fewer than 2 points");
      }
      line.name = where.Feature(fid);
      out->push_back(std::move(line));
      return Status::OK();
    }
    case wkbMultiLineString:
      for (const OGRLineString* part : *g.toMultiLineString()) {
        if (Status status = ReadBreakline(where, fid, *part, keep_z, out);
            !status.ok()) {
          return status;
        }
      }
      return Status::OK();
    default:
      return where.Bad(fid, std::string("a ") + g.getGeometryName() +
                                " where breaklines are expected (LineString, "
                                "MultiLineString)");
  }
}

// The rings of one domain feature, exterior and interior alike.
Status ReadDomain(const Where& where, GIntBig fid, const OGRGeometry& g,
                  std::vector<Polyline>* out) {
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbPolygon: {
      size_t index = 0;  // 0: the exterior ring
      for (const OGRLinearRing* ring : *g.toPolygon()) {
        Polyline polyline;
        polyline.name =
            where.Feature(fid) +
            (index == 0 ? ", exterior ring"
                        : ", interior ring " + std::to_string(index));
        ++index;
        if (Status status = AppendCurve(where, fid, *ring, false, &polyline);
            !status.ok()) {
          return status;
        }
        const auto& p = polyline.points;
        if (p.size() > 1 && p.front().x == p.back().x &&
            p.front().y == p.back().y) {
          polyline.points.pop_back();  // rings close implicitly
        }
        if (polyline.points.size() < 3) {
          return where.Bad(fid, "a ring with fewer than 3 distinct points");
        }
        out->push_back(std::move(polyline));
      }
      return Status::OK();
    }
    case wkbMultiPolygon:
      for (const OGRPolygon* part : *g.toMultiPolygon()) {
        if (Status status = ReadDomain(where, fid, *part, out); !status.ok()) {
          return status;
        }
      }
      return Status::OK();
    default:
      return where.Bad(fid, std::string("a ") + g.getGeometryName() +
                                " where domain polygons are expected "
                                "(Polygon, MultiPolygon)");
  }
}

// Reads every feature of a breaklines (domain == false) or domain layer.
Status ReadConstraintLayer(const Where& where, OGRLayer& layer, bool domain,
                           bool keep_z, DatasetConstraints* out) {
  size_t features = 0;
  for (const OGRFeatureUniquePtr& feature : layer) {
    ++features;
    const OGRGeometry* geometry = feature->GetGeometryRef();
    const GIntBig fid = feature->GetFID();
    if (geometry == nullptr) return where.Bad(fid, "no geometry");
    if (geometry->IsEmpty()) return where.Bad(fid, "empty geometry");
    const Status status =
        domain ? ReadDomain(where, fid, *geometry, &out->rings)
               : ReadBreakline(where, fid, *geometry, keep_z, &out->breaklines);
    if (!status.ok()) return status;
  }
  if (features == 0) {
    return Status::InvalidArgument(where.Prefix() + " has no features");
  }
  return Status::OK();
}

std::string ToWkt(const OGRSpatialReference& srs) {
  char* wkt = nullptr;
  const char* const options[] = {"FORMAT=WKT2_2019", nullptr};
  srs.exportToWkt(&wkt, options);
  std::string out = wkt == nullptr ? "" : wkt;
  CPLFree(wkt);
  return out;
}

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
      return Status::InvalidArgument(spec.source + ": unknown CRS '" +
                                     spec.assigned_crs +
                                     "' (a_srs): " + LastGdalError());
    }
    *wkt = ToWkt(srs);
    return Status::OK();
  }
  OGRLayer* first = nullptr;
  for (OGRLayer* layer : layers) {
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    if (srs == nullptr) continue;
    if (first == nullptr) {
      first = layer;
      *wkt = ToWkt(*srs);
    } else if (!srs->IsSame(first->GetSpatialRef())) {
      return Status::InvalidArgument(
          spec.source + ": layer '" + layer->GetName() + "' is in CRS '" +
          srs->GetName() + "' but layer '" + first->GetName() + "' is in '" +
          first->GetSpatialRef()->GetName() + "' (a_srs= assigns one CRS)");
    }
  }
  return Status::OK();
}

}  // namespace

Status LoadOgrDataset(const std::string& spec_text, Dataset* out,
                      const DatasetLimits& limits) {
  OgrDatasetSpec spec;
  if (Status status = ParseOgrDatasetSpec(spec_text, &spec); !status.ok()) {
    return status;
  }
  // GDAL reports through its error state, not stderr.
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  GDALDatasetUniquePtr source;
  if (Status status = OpenSource(spec, &source); !status.ok()) return status;

  Dataset dataset;
  dataset.source = spec_text;
  OGRLayer* points = nullptr;
  if (Status status = FindLayer(*source, spec.source, spec.layer, &points);
      !status.ok()) {
    return status;
  }
  std::vector<OGRLayer*> layers = {points};
  if (Status status =
          PointReader(Where{spec.source, points->GetName()}, limits, &dataset)
              .Read(*points, spec);
      !status.ok()) {
    return status;
  }
  for (const bool domain : {false, true}) {
    const std::string& name =
        domain ? spec.domain_layer : spec.breaklines_layer;
    if (name.empty()) continue;
    OGRLayer* layer = nullptr;
    if (Status status = FindLayer(*source, spec.source, name, &layer);
        !status.ok()) {
      return status;
    }
    layers.push_back(layer);
    if (Status status =
            ReadConstraintLayer(Where{spec.source, name}, *layer, domain,
                                dataset.has_values(), &dataset.constraints);
        !status.ok()) {
      return status;
    }
  }
  if (Status status = ResolveCrs(spec, layers, &dataset.crs); !status.ok()) {
    return status;
  }
  *out = std::move(dataset);
  return Status::OK();
}

}  // namespace locator::gis
