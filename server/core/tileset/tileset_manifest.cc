#include "server/core/tileset/tileset_manifest.h"

#include <charconv>
#include <cstdio>
#include <span>
#include <system_error>
#include <utility>

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

// The value of the top-level member `key` of `text`: the text after
// "key": (every '"' inside a JsonWriter string is escaped, so the first
// such run is the member). Empty if there is none.
std::string_view ValueOf(std::string_view text, std::string_view key) {
  const std::string pattern = "\"" + std::string(key) + "\":";
  const size_t at = text.find(pattern);
  if (at == std::string_view::npos) return {};
  return text.substr(at + pattern.size());
}

// Decodes the JSON string at the start of `value` into *out.
bool ParseString(std::string_view value, std::string* out) {
  if (value.empty() || value[0] != '"') return false;
  out->clear();
  for (size_t k = 1; k < value.size(); ++k) {
    const char c = value[k];
    if (c == '"') return true;
    if (c != '\\') {
      out->push_back(c);
      continue;
    }
    if (++k == value.size()) return false;
    switch (value[k]) {
      case 'n':
        out->push_back('\n');
        break;
      case 't':
        out->push_back('\t');
        break;
      case 'r':
        out->push_back('\r');
        break;
      case 'b':
        out->push_back('\b');
        break;
      case 'f':
        out->push_back('\f');
        break;
      case 'u': {
        unsigned code = 0;
        if (k + 4 >= value.size() ||
            std::sscanf(std::string(value.substr(k + 1, 4)).c_str(), "%4x",
                        &code) != 1) {
          return false;
        }
        k += 4;
        if (code < 0x80) {
          out->push_back(static_cast<char>(code));
        } else if (code < 0x800) {
          out->push_back(static_cast<char>(0xc0 | code >> 6));
          out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
        } else {
          out->push_back(static_cast<char>(0xe0 | code >> 12));
          out->push_back(static_cast<char>(0x80 | (code >> 6 & 0x3f)));
          out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
        }
        break;
      }
      default:
        out->push_back(value[k]);  // '"', '\\', '/'
    }
  }
  return false;
}

bool ParseUnsigned(std::string_view value, uint64_t* out, int base) {
  const auto [end, error] =
      std::from_chars(value.data(), value.data() + value.size(), *out, base);
  return error == std::errc() && end != value.data();
}

// Parses the JSON array of numbers at the start of `value` (as JsonWriter
// writes one: no spaces) into *out, which must hold exactly that many.
template <typename Number>
bool ParseArray(std::string_view value, std::span<Number> out) {
  if (value.empty() || value[0] != '[') return false;
  const char* at = value.data() + 1;
  const char* const end = value.data() + value.size();
  for (size_t k = 0; k < out.size(); ++k) {
    if (k > 0) {
      if (at == end || *at != ',') return false;
      ++at;
    }
    const auto [next, error] = std::from_chars(at, end, out[k]);
    if (error != std::errc() || next == at) return false;
    at = next;
  }
  return at != end && *at == ']';
}

// The first cell of each tile in the manifest's "tiles" array (every
// "cells": member after it, in order), checked to follow each other from
// cell 0 up to 4^level.
bool ParseTileCells(std::string_view text, int level,
                    std::vector<uint32_t>* first_cells) {
  const size_t tiles_at = text.find("\"tiles\":[");
  if (tiles_at == std::string_view::npos) return false;
  constexpr std::string_view kCells = "\"cells\":";
  uint64_t expected_first = 0;
  for (size_t at = text.find(kCells, tiles_at); at != std::string_view::npos;
       at = text.find(kCells, at + 1)) {
    uint64_t range[2];
    if (!ParseArray<uint64_t>(text.substr(at + kCells.size()), range) ||
        range[0] != expected_first || range[1] <= range[0]) {
      return false;
    }
    first_cells->push_back(static_cast<uint32_t>(range[0]));
    expected_first = range[1];
  }
  return !first_cells->empty() && expected_first == uint64_t{1} << (2 * level);
}

}  // namespace

Status ParseManifestSummary(std::string_view text, std::string_view name,
                            TileSetManifestSummary* out) {
  const auto bad = [&](std::string_view what) {
    return Status::InvalidArgument(std::string(name) + ": " +
                                   std::string(what));
  };
  std::string format, fingerprint;
  uint64_t version = 0;
  if (!ParseString(ValueOf(text, "format"), &format) ||
      format != "locator-tileset") {
    return bad("not a locator tile-set manifest (format)");
  }
  if (!ParseUnsigned(ValueOf(text, "version"), &version, 10) ||
      version != kTileSetManifestVersion) {
    return bad("manifest version is not " +
               std::to_string(kTileSetManifestVersion));
  }
  TileSetManifestSummary s;
  if (!ParseString(ValueOf(text, "source"), &s.source)) return bad("no source");
  if (!ParseString(ValueOf(text, "crs"), &s.crs)) return bad("no crs");
  if (!ParseString(ValueOf(text, "fingerprint"), &fingerprint) ||
      fingerprint.size() != 16 ||
      !ParseUnsigned(fingerprint, &s.fingerprint, 16)) {
    return bad("no fingerprint of 16 hex digits");
  }
  if (!ParseUnsigned(ValueOf(text, "input_points"), &s.input_points, 10)) {
    return bad("no input_points");
  }
  if (!ParseString(ValueOf(text, "mesh_file"), &s.mesh_file) ||
      s.mesh_file.empty() || s.mesh_file.find('/') != std::string::npos) {
    return bad("no mesh_file (a file name beside the manifest)");
  }
  double box[4];
  if (!ParseArray<double>(ValueOf(text, "bounds"), box) ||
      !(box[0] <= box[2] && box[1] <= box[3])) {
    return bad("no bounds [min_x,min_y,max_x,max_y]");
  }
  s.bounds = BoundingBox{box[0], box[1], box[2], box[3]};
  uint64_t level = 0;
  if (!ParseUnsigned(ValueOf(text, "grid_level"), &level, 10) || level > 15) {
    return bad("no grid_level of 0..15");
  }
  s.grid_level = static_cast<int>(level);
  if (!ParseTileCells(text, s.grid_level, &s.tile_first_cells)) {
    return bad("tiles' cells do not follow each other from cell 0");
  }
  *out = std::move(s);
  return Status::OK();
}

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
