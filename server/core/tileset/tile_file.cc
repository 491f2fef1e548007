#include "server/core/tileset/tile_file.h"

#include <bit>
#include <cstring>
#include <vector>

#include "common/status_macros.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/tileset/binary_files.h"

namespace locator {
namespace {

constexpr char kTileMagic[8] = {'l', 'o', 'c', 't', 'i', 'l', 'e', '\0'};
constexpr uint64_t kAlignment = 64;
static_assert(std::endian::native == std::endian::little,
              "tile files are little-endian");

struct TileHeader {
  char magic[8];
  uint32_t version;
  uint32_t number;
  uint64_t build_key;
  uint32_t first_cell, end_cell, first_vertex, end_vertex;
  uint64_t triangles;
  uint64_t halo_points;
  uint32_t rounds;
  uint32_t has_values;
  uint64_t file_bytes;
  uint64_t payload_checksum;
  uint64_t reserved[5];      // zero
  uint64_t header_checksum;  // of every byte before it
};
static_assert(sizeof(TileHeader) == kTileFileHeaderBytes);

uint64_t AlignUp(uint64_t offset) {
  return (offset + kAlignment - 1) / kAlignment * kAlignment;
}

// Where each section starts, and where the file ends.
struct Layout {
  uint64_t points, ids, values, triangles, end;
};

Layout LayoutOf(uint64_t vertices, bool has_values, uint64_t triangles) {
  Layout l;
  l.points = sizeof(TileHeader);
  l.ids = AlignUp(l.points + vertices * sizeof(Point2));
  l.values = AlignUp(l.ids + vertices * sizeof(uint32_t));
  l.triangles =
      AlignUp(l.values + (has_values ? vertices * sizeof(double) : 0));
  l.end = l.triangles + triangles * sizeof(MeshTriangle);
  return l;
}

uint64_t HeaderChecksum(const TileHeader& h) {
  return Xxh3Of(std::string_view(reinterpret_cast<const char*>(&h),
                                 offsetof(TileHeader, header_checksum)));
}

Status Bad(std::string_view what) {
  return Status::InvalidArgument("tile file: " + std::string(what));
}

Status CheckHeader(const TileHeader& h, uint64_t bytes, TileFileInfo* info) {
  if (std::memcmp(h.magic, kTileMagic, sizeof(kTileMagic)) != 0) {
    return Bad("not a tile file (magic)");
  }
  if (h.version != kTileFileVersion) {
    return Bad("version " + std::to_string(h.version) + ", expected " +
               std::to_string(kTileFileVersion));
  }
  if (h.header_checksum != HeaderChecksum(h)) {
    return Bad("header checksum mismatch");
  }
  if (h.end_vertex < h.first_vertex || h.end_cell < h.first_cell ||
      h.triangles > ServingMesh::kMaxElements) {
    return Bad("ranges out of order");
  }
  const Layout l =
      LayoutOf(h.end_vertex - h.first_vertex, h.has_values != 0, h.triangles);
  if (h.file_bytes != l.end || bytes != l.end) {
    return Bad("length " + std::to_string(bytes) + ", the header says " +
               std::to_string(l.end));
  }
  info->build_key = h.build_key;
  info->number = h.number;
  info->tile = Tile{h.first_cell, h.end_cell, h.first_vertex, h.end_vertex};
  info->triangles = h.triangles;
  info->halo_points = h.halo_points;
  info->rounds = h.rounds;
  info->has_values = h.has_values != 0;
  info->file_bytes = h.file_bytes;
  info->checksum = h.payload_checksum;
  return Status::OK();
}

std::string_view Bytes(const void* data, size_t size) {
  return {static_cast<const char*>(data), size};
}

}  // namespace

Status WriteTileFile(const std::string& path, std::span<const Point2> points,
                     std::span<const uint32_t> ids,
                     std::span<const double> values,
                     std::span<const MeshTriangle> triangles,
                     TileFileInfo* info) {
  const bool has_values = !values.empty();
  const Layout l = LayoutOf(points.size(), has_values, triangles.size());
  static const char kZeros[kAlignment] = {};
  const auto padding = [](uint64_t from, uint64_t to) {
    return std::string_view(kZeros, to - from);
  };
  std::vector<std::string_view> payload = {
      Bytes(points.data(), points.size_bytes()),
      padding(l.points + points.size_bytes(), l.ids),
      Bytes(ids.data(), ids.size_bytes()),
      padding(l.ids + ids.size_bytes(), l.values),
      Bytes(values.data(), values.size_bytes()),
      padding(l.values + values.size_bytes(), l.triangles),
      Bytes(triangles.data(), triangles.size_bytes())};
  Xxh3Digest digest;
  for (const std::string_view piece : payload) digest.Add(piece);

  TileHeader h{};
  std::memcpy(h.magic, kTileMagic, sizeof(kTileMagic));
  h.version = kTileFileVersion;
  h.number = info->number;
  h.build_key = info->build_key;
  h.first_cell = info->tile.first_cell;
  h.end_cell = info->tile.end_cell;
  h.first_vertex = info->tile.first_vertex;
  h.end_vertex = info->tile.end_vertex;
  h.triangles = triangles.size();
  h.halo_points = info->halo_points;
  h.rounds = info->rounds;
  h.has_values = has_values;
  h.file_bytes = l.end;
  h.payload_checksum = digest.digest();
  h.header_checksum = HeaderChecksum(h);
  payload.insert(payload.begin(), Bytes(&h, sizeof(h)));
  RETURN_IF_ERROR(WriteFileAtomically(path, payload));
  info->triangles = triangles.size();
  info->has_values = has_values;
  info->file_bytes = l.end;
  info->checksum = h.payload_checksum;
  return Status::OK();
}

Status ReadTileFileInfo(const std::string& path, TileFileInfo* info) {
  RandomAccessFile file;
  RETURN_IF_ERROR(file.Open(path));
  TileHeader h;
  if (file.size() < sizeof(h)) return Bad("shorter than its header");
  RETURN_IF_ERROR(file.ReadAt(0, &h, sizeof(h)));
  return CheckHeader(h, file.size(), info);
}

Status DecodeTileFile(std::string_view bytes, TileFileInfo* info,
                      TileFileArrays* arrays) {
  TileHeader h;
  if (bytes.size() < sizeof(h)) return Bad("shorter than its header");
  std::memcpy(&h, bytes.data(), sizeof(h));
  RETURN_IF_ERROR(CheckHeader(h, bytes.size(), info));
  if (Xxh3Of(bytes.substr(sizeof(h))) != h.payload_checksum) {
    return Bad("payload checksum mismatch");
  }
  const uint64_t vertices = h.end_vertex - h.first_vertex;
  const Layout l = LayoutOf(vertices, h.has_values != 0, h.triangles);
  const char* base = bytes.data();
  arrays->points = {reinterpret_cast<const Point2*>(base + l.points), vertices};
  arrays->ids = {reinterpret_cast<const uint32_t*>(base + l.ids), vertices};
  arrays->values = {reinterpret_cast<const double*>(base + l.values),
                    h.has_values != 0 ? vertices : 0};
  arrays->triangles = {
      reinterpret_cast<const MeshTriangle*>(base + l.triangles), h.triangles};
  return Status::OK();
}

}  // namespace locator
