#include "common/gis/ogr_constraints.h"

#include <utility>
#include <vector>

#include "common/status_macros.h"

namespace locator::gis {
namespace {

// Appends `curve`'s points to *line; Z values too when `keep_z`.
Status AppendCurve(const FeatureLocation& where, GIntBig fid,
                   const OGRSimpleCurve& curve, bool keep_z, Polyline* line) {
  for (const OGRPoint& point : curve) {
    RETURN_IF_ERROR(CheckFinite(where, fid, point));
    line->points.push_back(Point2{point.getX(), point.getY()});
    if (keep_z) line->values.push_back(point.getZ());
  }
  return Status::OK();
}

// The polylines of one breaklines feature.
Status ReadBreakline(const FeatureLocation& where, GIntBig fid,
                     const OGRGeometry& g, bool keep_z,
                     std::vector<Polyline>* out) {
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbLineString: {
      Polyline line;
      RETURN_IF_ERROR(AppendCurve(where, fid, *g.toLineString(),
                                  keep_z && g.Is3D(), &line));
      if (line.points.size() < 2) {
        return where.Bad(fid, "a breakline with fewer than 2 points");
      }
      line.name = where.Feature(fid);
      out->push_back(std::move(line));
      return Status::OK();
    }
    case wkbMultiLineString:
      for (const OGRLineString* part : *g.toMultiLineString()) {
        RETURN_IF_ERROR(ReadBreakline(where, fid, *part, keep_z, out));
      }
      return Status::OK();
    default:
      return where.Bad(fid, std::string("a ") + g.getGeometryName() +
                                " where breaklines are expected (LineString, "
                                "MultiLineString)");
  }
}

// The rings of one domain feature, exterior and interior alike.
Status ReadDomain(const FeatureLocation& where, GIntBig fid,
                  const OGRGeometry& g, std::vector<Polyline>* out) {
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
        RETURN_IF_ERROR(AppendCurve(where, fid, *ring, false, &polyline));
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
        RETURN_IF_ERROR(ReadDomain(where, fid, *part, out));
      }
      return Status::OK();
    default:
      return where.Bad(fid, std::string("a ") + g.getGeometryName() +
                                " where domain polygons are expected "
                                "(Polygon, MultiPolygon)");
  }
}

}  // namespace

Status ReadConstraintLayer(const FeatureLocation& where, OGRLayer& layer,
                           bool domain, bool keep_z, DatasetConstraints* out) {
  size_t features = 0;
  RETURN_IF_ERROR(ForEachFeature(where, layer, [&](const OGRFeature& feature) {
    ++features;
    const OGRGeometry* geometry = feature.GetGeometryRef();
    const GIntBig fid = feature.GetFID();
    if (geometry == nullptr) return where.Bad(fid, "no geometry");
    if (geometry->IsEmpty()) return where.Bad(fid, "empty geometry");
    return domain
               ? ReadDomain(where, fid, *geometry, &out->rings)
               : ReadBreakline(where, fid, *geometry, keep_z, &out->breaklines);
  }));
  if (features == 0) {
    return Status::InvalidArgument(where.Prefix() + " has no features");
  }
  return Status::OK();
}

}  // namespace locator::gis
