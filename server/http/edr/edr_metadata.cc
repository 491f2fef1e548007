#include "server/http/edr/edr_metadata.h"

#include <string>
#include <vector>

#include "server/http/edr/coverage_json.h"
#include "server/http/edr/edr_parameters.h"

namespace locator {
namespace {

void WriteLink(JsonWriter* json, const std::string& href, std::string_view rel,
               std::string_view type, std::string_view title) {
  json->BeginObject()
      .Key("href")
      .String(href)
      .Key("rel")
      .String(rel)
      .Key("type")
      .String(type)
      .Key("title")
      .String(title)
      .EndObject();
}

void WriteBox(JsonWriter* json, double min_x, double min_y, double max_x,
              double max_y) {
  json->BeginArray()
      .BeginArray()
      .Number(min_x)
      .Number(min_y)
      .Number(max_x)
      .Number(max_y)
      .EndArray()
      .EndArray();
}

void WriteQuery(JsonWriter* json, const std::string& collection,
                std::string_view query, std::string_view title,
                const std::vector<EdrCrs>& crs) {
  json->Key(query).BeginObject().Key("link").BeginObject();
  json->Key("href")
      .String(collection + "/" + std::string(query))
      .Key("rel")
      .String("data")
      .Key("title")
      .String(title)
      .Key("variables")
      .BeginObject()
      .Key("query_type")
      .String(query)
      .Key("output_formats")
      .BeginArray()
      .String(EdrFormatName(EdrFormat::kCoverageJson))
      .String(EdrFormatName(EdrFormat::kGeoJson))
      .EndArray()
      .Key("default_output_format")
      .String(EdrFormatName(EdrFormat::kCoverageJson))
      .Key("crs_details")
      .BeginArray();
  for (const EdrCrs& c : crs) {
    json->BeginObject().Key("crs").String(c.uri).Key("wkt").String(c.wkt);
    json->EndObject();
  }
  json->EndArray().EndObject().EndObject().EndObject();
}

}  // namespace

std::string EdrLandingPage() {
  const std::string root(kEdrPath);
  JsonWriter json;
  json.BeginObject()
      .Key("title")
      .String("locator: OGC API - Environmental Data Retrieval")
      .Key("description")
      .String(
          "Values of this server's TINs at points (position) and along lines "
          "(trajectory), as CoverageJSON or GeoJSON")
      .Key("links")
      .BeginArray();
  WriteLink(&json, root + "/", "self", "application/json", "This document");
  WriteLink(&json, root + "/conformance", "conformance", "application/json",
            "Conformance classes");
  WriteLink(&json, root + "/collections", "data", "application/json",
            "Collections: one per dataset");
  json.EndArray().EndObject();
  return json.TakeText();
}

std::string EdrConformance() {
  JsonWriter json;
  json.BeginObject().Key("conformsTo").BeginArray();
  for (const char* name :
       {"core", "collections", "json", "geojson", "covjson"}) {
    json.String(
        std::string("http://www.opengis.net/spec/ogcapi-edr-1/1.0/conf/") +
        name);
  }
  json.EndArray().EndObject();
  return json.TakeText();
}

void WriteEdrCollection(const EdrCollectionFacts& facts, JsonWriter* json) {
  const v1::DatasetStats& stats = facts.stats;
  const std::string self =
      std::string(kEdrPath) + "/collections/" + stats.name();
  const std::vector<EdrCrs> crs = OfferedCrs(stats);
  json->BeginObject()
      .Key("id")
      .String(stats.name())
      .Key("title")
      .String(stats.name())
      .Key("description")
      .String(stats.has_crs() ? "TIN in " + stats.crs().name()
                              : std::string("TIN without a CRS: query it in "
                                            "its own coordinates"))
      .Key("links")
      .BeginArray();
  WriteLink(json, self, "self", "application/json", "This collection");
  json->EndArray();

  // The extent: longitude/latitude as EDR wants it where there is a CRS,
  // and always the dataset's own box (locator's extension).
  const v1::BoundingBox& box = stats.bounding_box();
  json->Key("extent").BeginObject().Key("spatial").BeginObject();
  if (facts.lon_lat_box.has_value()) {
    const BoundingBox& ll = *facts.lon_lat_box;
    json->Key("bbox");
    WriteBox(json, ll.min_x, ll.min_y, ll.max_x, ll.max_y);
    json->Key("crs").String(kCrs84Uri);
  }
  json->Key("native_bbox");
  WriteBox(json, box.min_x(), box.min_y(), box.max_x(), box.max_y());
  json->Key("native_crs")
      .String(crs.back().wkt.empty() ? kDatasetCrsName : crs.back().wkt);
  json->EndObject().EndObject();

  json->Key("data_queries").BeginObject();
  WriteQuery(json, self, "position", "Values at points", crs);
  WriteQuery(json, self, "trajectory", "Values along a line", crs);
  json->EndObject();
  json->Key("crs").BeginArray();
  for (const EdrCrs& c : crs) json->String(c.uri);
  json->EndArray();
  json->Key("output_formats")
      .BeginArray()
      .String(EdrFormatName(EdrFormat::kCoverageJson))
      .String(EdrFormatName(EdrFormat::kGeoJson))
      .EndArray();
  json->Key("parameter_names").BeginObject().Key(kElevationParameter);
  WriteElevationParameter(json);
  json->EndObject().EndObject();
}

}  // namespace locator
