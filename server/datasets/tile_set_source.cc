#include "server/datasets/tile_set_source.h"

#include <filesystem>

#include "common/status_macros.h"
#include "server/core/dataset/file_io.h"

namespace locator {
namespace {

constexpr std::string_view kPrefix = "tileset:";
constexpr std::string_view kManifestName = "manifest.json";
// A manifest lists every tile; far below this for any tile set.
constexpr size_t kMaxManifestBytes = size_t{256} << 20;

std::string_view PathOf(std::string_view spec) {
  return spec.starts_with(kPrefix) ? spec.substr(kPrefix.size()) : spec;
}

}  // namespace

bool IsTileSetSpec(std::string_view spec) {
  if (spec.starts_with(kPrefix)) return true;
  return spec == kManifestName ||
         (spec.ends_with(kManifestName) &&
          spec[spec.size() - kManifestName.size() - 1] == '/');
}

Status ReadTileSetSpec(std::string_view spec, TileSetManifestSummary* manifest,
                       std::string* dir) {
  const std::string path(PathOf(spec));
  std::string text;
  RETURN_IF_ERROR(
      ReadWholeFile(path, "tile-set manifest", &text, kMaxManifestBytes));
  RETURN_IF_ERROR(ParseManifestSummary(text, path, manifest));
  *dir = std::filesystem::path(path).parent_path().string();
  if (dir->empty()) *dir = ".";
  return Status::OK();
}

}  // namespace locator
