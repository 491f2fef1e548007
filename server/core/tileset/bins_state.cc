#include "server/core/tileset/bins_state.h"

#include <cstring>
#include <string_view>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"

namespace locator {
namespace {

constexpr char kBinsMagic[8] = {'l', 'o', 'c', 'b', 'i', 'n', 's', '\0'};
constexpr uint32_t kBinsVersion = 1;

struct BinsHeader {
  char magic[8];
  uint32_t version;
  int32_t level;
  uint64_t key;
  double box[4];
  uint64_t input_points, vertices, has_values, fingerprint, bins;
  uint64_t cells, candidates;  // entries of cell_start and hull_candidates
};

std::string StatePath(const std::string& dir) { return dir + "/bins.state"; }

Status Unusable(const std::string& dir, std::string_view why) {
  return Status::NotFound(StatePath(dir) + ": " + std::string(why));
}

}  // namespace

Status SaveBinsState(const std::string& dir, uint64_t key,
                     const BinnedPoints& binned) {
  BinsHeader h{};
  std::memcpy(h.magic, kBinsMagic, sizeof(kBinsMagic));
  h.version = kBinsVersion;
  h.level = binned.grid.level();
  h.key = key;
  const BoundingBox& box = binned.grid.box();
  h.box[0] = box.min_x;
  h.box[1] = box.min_y;
  h.box[2] = box.max_x;
  h.box[3] = box.max_y;
  h.input_points = binned.input_points;
  h.vertices = binned.vertices;
  h.has_values = binned.has_values;
  h.fingerprint = binned.fingerprint;
  h.bins = binned.bins;
  h.cells = binned.cell_start.size();
  h.candidates = binned.hull_candidates.size();
  const std::string_view pieces[] = {
      {reinterpret_cast<const char*>(&h), sizeof(h)},
      {reinterpret_cast<const char*>(binned.cell_start.data()),
       binned.cell_start.size() * sizeof(uint32_t)},
      {reinterpret_cast<const char*>(binned.hull_candidates.data()),
       binned.hull_candidates.size() * sizeof(uint32_t)}};
  Xxh3Digest digest;
  for (const std::string_view piece : pieces) digest.Add(piece);
  const uint64_t checksum = digest.digest();
  const std::string_view all[] = {
      pieces[0],
      pieces[1],
      pieces[2],
      {reinterpret_cast<const char*>(&checksum), sizeof(checksum)}};
  return WriteFileAtomically(StatePath(dir), all);
}

Status LoadBinsState(const std::string& dir, uint64_t key, BinnedPoints* out) {
  std::string bytes;
  const Status read = ReadWholeFile(StatePath(dir), "bins state", &bytes);
  if (!read.ok()) return Unusable(dir, read.message());
  BinsHeader h;
  if (bytes.size() < sizeof(h) + sizeof(uint64_t)) {
    return Unusable(dir, "too short");
  }
  std::memcpy(&h, bytes.data(), sizeof(h));
  if (std::memcmp(h.magic, kBinsMagic, sizeof(kBinsMagic)) != 0 ||
      h.version != kBinsVersion) {
    return Unusable(dir, "not a bins state of this version");
  }
  if (h.key != key) return Unusable(dir, "made for another source");
  const uint64_t body = sizeof(h) + (h.cells + h.candidates) * sizeof(uint32_t);
  if (bytes.size() != body + sizeof(uint64_t) || h.level < 0 ||
      h.level > CellGrid::kMaxLevel) {
    return Unusable(dir, "damaged");
  }
  uint64_t checksum;
  std::memcpy(&checksum, bytes.data() + body, sizeof(checksum));
  if (checksum != Xxh3Of(std::string_view(bytes.data(), body))) {
    return Unusable(dir, "checksum mismatch");
  }
  BinnedPoints binned;
  binned.grid =
      CellGrid(BoundingBox{h.box[0], h.box[1], h.box[2], h.box[3]}, h.level);
  if (h.cells != binned.grid.num_cells() + 1) return Unusable(dir, "damaged");
  binned.input_points = h.input_points;
  binned.vertices = h.vertices;
  binned.has_values = h.has_values != 0;
  binned.fingerprint = h.fingerprint;
  binned.bins = h.bins;
  binned.cell_start.resize(h.cells);
  std::memcpy(binned.cell_start.data(), bytes.data() + sizeof(h),
              h.cells * sizeof(uint32_t));
  binned.hull_candidates.resize(h.candidates);
  std::memcpy(binned.hull_candidates.data(),
              bytes.data() + sizeof(h) + h.cells * sizeof(uint32_t),
              h.candidates * sizeof(uint32_t));
  *out = std::move(binned);
  return Status::OK();
}

}  // namespace locator
