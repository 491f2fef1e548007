#include "server/core/tileset/tileset_manifest.h"

#include <cstdio>

#include "common/json_writer.h"

namespace locator {
namespace {

std::string Hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx",
                static_cast<unsigned long long>(value));
  return text;
}

void WriteBox(const BoundingBox& box, JsonWriter* json) {
  json->BeginArray()
      .Number(box.min_x)
      .Number(box.min_y)
      .Number(box.max_x)
      .Number(box.max_y)
      .EndArray();
}

void WriteRange(uint64_t first, uint64_t end, JsonWriter* json) {
  json->BeginArray().Integer(first).Integer(end).EndArray();
}

}  // namespace

std::string ManifestJson(const TileSetManifest& m) {
  uint64_t triangles = 0, halo_points = 0, file_bytes = 0;
  for (const TileSetManifest::TileEntry& t : m.tiles) {
    triangles += t.info.triangles;
    halo_points += t.info.halo_points;
    file_bytes += t.info.file_bytes;
  }
  JsonWriter json;
  json.BeginObject();
  json.Key("format").String("locator-tileset");
  json.Key("version").Integer(kTileSetManifestVersion);
  json.Key("tile_file_version").Integer(kTileFileVersion);
  json.Key("source").String(m.source);
  json.Key("crs").String(m.crs);
  json.Key("fingerprint").String(Hex(m.fingerprint));
  json.Key("build_key").String(Hex(m.build_key));
  json.Key("input_points").Integer(m.input_points);
  json.Key("vertices").Integer(m.vertices);
  json.Key("duplicates_merged").Integer(m.input_points - m.vertices);
  json.Key("has_values").Bool(m.has_values);
  json.Key("bounds");
  WriteBox(m.bounds, &json);
  json.Key("mesh_file").String(m.mesh_file);
  json.Key("grid_level").Integer(static_cast<uint64_t>(m.grid_level));
  json.Key("hull").BeginArray();
  for (const uint32_t v : m.hull) json.Integer(v);
  json.EndArray();
  json.Key("statistics").BeginObject();
  json.Key("tiles").Integer(m.tiles.size());
  json.Key("triangles").Integer(triangles);
  json.Key("halo_points").Integer(halo_points);
  json.Key("file_bytes").Integer(file_bytes);
  json.Key("bytes_per_point")
      .Number(m.vertices > 0 ? static_cast<double>(file_bytes) / m.vertices
                             : 0.0);
  json.Key("build_seconds").Number(m.build_seconds);
  json.EndObject();
  json.Key("tiles").BeginArray();
  for (const TileSetManifest::TileEntry& t : m.tiles) {
    json.BeginObject();
    json.Key("file").String(t.file);
    json.Key("cells");
    WriteRange(t.info.tile.first_cell, t.info.tile.end_cell, &json);
    json.Key("vertices");
    WriteRange(t.info.tile.first_vertex, t.info.tile.end_vertex, &json);
    json.Key("triangles").Integer(t.info.triangles);
    json.Key("halo_points").Integer(t.info.halo_points);
    json.Key("rounds").Integer(t.info.rounds);
    json.Key("bounds");
    WriteBox(t.bounds, &json);
    json.Key("file_bytes").Integer(t.info.file_bytes);
    json.Key("checksum").String(Hex(t.info.checksum));
    json.EndObject();
  }
  json.EndArray();
  json.EndObject();
  return json.TakeText();
}

}  // namespace locator
