#include "server/http/edr/coverage_json.h"

namespace locator {
namespace {

void WriteReferencing(const EdrCrs& crs, JsonWriter* json) {
  json->Key("referencing")
      .BeginArray()
      .BeginObject()
      .Key("coordinates")
      .BeginArray()
      .String("x")
      .String("y")
      .EndArray()
      .Key("system")
      .BeginObject()
      .Key("type")
      .String(crs.lon_lat ? "GeographicCRS" : "ProjectedCRS");
  // A CRS with a URI is named by it; the dataset's own by its WKT.
  if (crs.uri != kDatasetCrsName) {
    json->Key("id").String(crs.uri);
  } else if (!crs.wkt.empty()) {
    json->Key("wkt").String(crs.wkt);
  }
  json->EndObject().EndObject().EndArray();
}

void WriteDomain(const CoveragePoints& points, const EdrCrs& crs,
                 JsonWriter* json) {
  using Domain = CoveragePoints::Domain;
  json->Key("domain").BeginObject().Key("type").String("Domain");
  json->Key("domainType")
      .String(points.domain == Domain::kPoint        ? "Point"
              : points.domain == Domain::kMultiPoint ? "MultiPoint"
                                                     : "Trajectory");
  json->Key("axes").BeginObject();
  if (points.domain == Domain::kPoint) {
    json->Key("x").BeginObject().Key("values").BeginArray();
    json->Number(points.where[0].x).EndArray().EndObject();
    json->Key("y").BeginObject().Key("values").BeginArray();
    json->Number(points.where[0].y).EndArray().EndObject();
  } else {
    json->Key("composite")
        .BeginObject()
        .Key("dataType")
        .String("tuple")
        .Key("coordinates")
        .BeginArray()
        .String("x")
        .String("y")
        .EndArray()
        .Key("values")
        .BeginArray();
    for (const Point2& p : points.where) {
      json->BeginArray().Number(p.x).Number(p.y).EndArray();
    }
    json->EndArray().EndObject();
  }
  json->EndObject();
  WriteReferencing(crs, json);
  json->EndObject();
}

void WriteRange(const CoveragePoints& points, JsonWriter* json) {
  json->Key("ranges")
      .BeginObject()
      .Key(kElevationParameter)
      .BeginObject()
      .Key("type")
      .String("NdArray")
      .Key("dataType")
      .String("float")
      .Key("axisNames")
      .BeginArray();
  const bool single = points.domain == CoveragePoints::Domain::kPoint;
  if (single) {
    json->String("y").String("x");
  } else {
    json->String("composite");
  }
  json->EndArray().Key("shape").BeginArray();
  if (single) {
    json->Integer(1).Integer(1);
  } else {
    json->Integer(points.values.size());
  }
  json->EndArray().Key("values").BeginArray();
  // JsonWriter writes a non-finite number (no value) as null.
  for (const double value : points.values) json->Number(value);
  json->EndArray().EndObject().EndObject();
}

std::string CoverageJsonText(const CoveragePoints& points, const EdrCrs& crs) {
  JsonWriter json;
  json.Reserve(points.where.size() * 64 + 1024);
  json.BeginObject().Key("type").String("Coverage");
  WriteDomain(points, crs, &json);
  json.Key("parameters").BeginObject().Key(kElevationParameter);
  WriteElevationParameter(&json);
  json.EndObject();
  WriteRange(points, &json);
  json.EndObject();
  return json.TakeText();
}

std::string GeoJsonText(const CoveragePoints& points) {
  JsonWriter json;
  json.Reserve(points.where.size() * 128 + 64);
  json.BeginObject()
      .Key("type")
      .String("FeatureCollection")
      .Key("features")
      .BeginArray();
  for (size_t i = 0; i < points.where.size(); ++i) {
    json.BeginObject()
        .Key("type")
        .String("Feature")
        .Key("geometry")
        .BeginObject()
        .Key("type")
        .String("Point")
        .Key("coordinates")
        .BeginArray()
        .Number(points.where[i].x)
        .Number(points.where[i].y)
        .EndArray()
        .EndObject()
        .Key("properties")
        .BeginObject()
        .Key(kElevationParameter)
        .Number(points.values[i]);
    if (!points.distances.empty()) {
      json.Key("distance").Number(points.distances[i]);
    }
    json.EndObject().EndObject();
  }
  json.EndArray().EndObject();
  return json.TakeText();
}

}  // namespace

void WriteElevationParameter(JsonWriter* json) {
  json->BeginObject()
      .Key("type")
      .String("Parameter")
      .Key("description")
      .BeginObject()
      .Key("en")
      .String("The dataset's value (z), interpolated over its TIN")
      .EndObject()
      .Key("observedProperty")
      .BeginObject()
      .Key("label")
      .BeginObject()
      .Key("en")
      .String("Elevation")
      .EndObject()
      .EndObject()
      .EndObject();
}

std::string CoverageText(const CoveragePoints& points, const EdrCrs& crs,
                         EdrFormat format) {
  return format == EdrFormat::kGeoJson ? GeoJsonText(points)
                                       : CoverageJsonText(points, crs);
}

}  // namespace locator
