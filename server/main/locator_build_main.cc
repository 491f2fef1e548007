// locator-build: builds the tile set of a dataset out of core (tiles with
// certified halos, one file each, and a manifest; server/core/tileset),
// for datasets larger than a build in memory allows.
//
//   locator-build SOURCE --out DIR [--max-memory SIZE] [--threads N]
//
// SOURCE is any plain point dataset spec locatord takes (a generator, a
// text or LAS file, an OGR layer of points); generators are streamed, the
// others are read whole first. A progress line on stderr shows the tiles
// done, points per second and the time left; the summary goes to stdout.
// Run again after a kill, it keeps the sorted points and the tiles already
// written. Exit codes: 0 built, 1 the build failed, 2 bad flags.

#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "common/flags/flag_set.h"
#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tileset/tileset_build.h"
#include "server/datasets/dataset_source.h"
#include "server/datasets/source_key.h"

namespace locator {
namespace {

constexpr char kProgram[] = "locator-build";

struct BuildFlags {
  std::string out;
  uint64_t max_memory = uint64_t{4} << 30;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  uint64_t tile_points = 0;
  bool quiet = false;
};

// What a file source's key adds: each file's identity as the mesh cache
// keys it (IdentifyFile: size, modification time, device and inode).
std::string FilesKey(const std::vector<std::string>& files) {
  std::string key;
  for (const std::string& file : files) {
    const FileIdentity f = IdentifyFile(file);
    if (!f.exists) continue;
    key += "\n" + f.path + " " + std::to_string(f.size) + " " +
           std::to_string(f.mtime_ns) + " " + std::to_string(f.device) + " " +
           std::to_string(f.inode);
  }
  return key;
}

// The stream of `spec`'s points: generated as read, or loaded whole.
Status OpenSource(const std::string& spec, unsigned threads,
                  std::unique_ptr<PointStream>* stream, TileSetSource* source) {
  source->name = spec;
  if (DatasetKindOf(spec) == DatasetKind::kGenerator) {
    ASSIGN_OR_RETURN(const GeneratorSpec generator, ParseGeneratorSpec(spec));
    source->key = generator.CanonicalKey();
    *stream = GeneratedPointStream(generator);
    return Status::OK();
  }
  ServedLoadOptions options;
  options.limits.max_points = ServingMesh::kMaxElements;
  options.threads = threads;
  ServedDataset served;
  RETURN_IF_ERROR(LoadServedDataset(spec, options, &served));
  if (!served.dataset.constraints.empty()) {
    return Status::Unimplemented(
        "'" + spec +
        "' has constraints or is a simplified TIN; locator-build tiles plain "
        "point sets only (serve it with locatord --dataset)");
  }
  source->key = spec + FilesKey(served.files);
  source->crs = served.dataset.crs;
  *stream = DatasetPointStream(std::move(served.dataset));
  return Status::OK();
}

// Prints "\r" progress lines to stderr, at most twice a second.
class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool quiet) : quiet_(quiet) {}

  void operator()(const TileSetProgress& p) {
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    switch (p.stage) {
      case TileSetProgress::Stage::kBinning:
        std::cerr << "sorting points to disk ..." << std::flush;
        return;
      case TileSetProgress::Stage::kMesh:
        std::cerr << "\nassembling the serving mesh ..." << std::flush;
        return;
      case TileSetProgress::Stage::kDone:
        std::cerr << " done\n";
        return;
      case TileSetProgress::Stage::kTiles:
        break;
    }
    if (!tiles_started_) {
      tiles_started_ = true;
      tiles_start_ = now;
      points_at_start_ = p.points_done;
      std::cerr << " done\n";
    } else if (p.tiles_done < p.tiles &&
               now - last_ < std::chrono::milliseconds(500)) {
      return;
    }
    last_ = now;
    const double seconds =
        std::chrono::duration<double>(now - tiles_start_).count();
    const double rate =
        seconds > 0 ? (p.points_done - points_at_start_) / seconds : 0;
    const double left = rate > 0 ? (p.points - p.points_done) / rate : 0;
    char line[160];
    std::snprintf(line, sizeof(line),
                  "\rtiles %zu/%zu  %.2f M points/s  ETA %.0f s   ",
                  p.tiles_done, p.tiles, rate / 1e6, left);
    std::cerr << line << std::flush;
  }

 private:
  const bool quiet_;
  bool tiles_started_ = false;
  std::chrono::steady_clock::time_point tiles_start_, last_;
  uint64_t points_at_start_ = 0;
};

int Run(int argc, char** argv) {
  BuildFlags f;
  std::vector<std::string> sources;
  FlagSet flags(
      "Usage: locator-build SOURCE --out DIR [flags]\n"
      "Builds the tile set of the plain point dataset SOURCE (any spec "
      "locatord --dataset takes) into DIR: tile files and manifest.json.");
  flags.AllowPositionals(&sources);
  flags.Add("out", flag::Text(&f.out), "the tile set's directory (created)");
  flags.Add("max-memory",
            flag::Bytes(&f.max_memory, 64 << 20, uint64_t{1} << 46),
            "the peak memory to stay within, roughly (bins and tiles are "
            "sized by it)");
  flags.Add("threads", flag::Count(&f.threads, 1, 256),
            "threads that triangulate tiles");
  flags.Add("tile-points", flag::Count(&f.tile_points, 0, uint64_t{1} << 31),
            "vertices per tile (0: from --max-memory and --threads)");
  flags.Add("quiet", flag::Switch(&f.quiet), "no progress line");
  Status parsed = flags.Parse(argc, argv);
  if (parsed.ok() && !flags.help_requested()) {
    if (sources.size() != 1) {
      parsed = Status::InvalidArgument("give exactly one SOURCE");
    } else if (f.out.empty()) {
      parsed = Status::InvalidArgument("--out DIR is required");
    }
  }
  if (std::optional<int> code = ExitCodeForFlags(
          kProgram, parsed, flags.help_requested() ? flags.Help() : "")) {
    return *code;
  }

  std::unique_ptr<PointStream> stream;
  TileSetSource source;
  Status status = OpenSource(sources[0], f.threads, &stream, &source);
  TileSetManifest manifest;
  TileSetStats stats;
  if (status.ok()) {
    TileSetOptions options;
    options.threads = f.threads;
    options.memory_bytes = f.max_memory;
    options.tile_points = f.tile_points;
    ProgressPrinter printer(f.quiet);
    status = BuildTileSet(
        stream.get(), source, f.out, options,
        [&](const TileSetProgress& p) { printer(p); }, &manifest, &stats);
  }
  if (!status.ok()) {
    std::cerr << "\n" << kProgram << ": " << status.ToString() << "\n";
    return 1;
  }
  uint64_t triangles = 0, tile_bytes = 0;
  for (const TileSetManifest::TileEntry& t : manifest.tiles) {
    triangles += t.info.triangles;
    tile_bytes += t.info.file_bytes;
  }
  struct stat mesh;
  const double mesh_bytes =
      ::stat((f.out + "/" + manifest.mesh_file).c_str(), &mesh) == 0
          ? static_cast<double>(mesh.st_size)
          : 0.0;
  struct rusage usage;
  ::getrusage(RUSAGE_SELF, &usage);
  const double vertices = static_cast<double>(manifest.vertices);
  std::printf(
      "%s: %llu points (%llu distinct), %zu tiles (%zu kept from an earlier "
      "run), %llu triangles\n"
      "  sort %.1f s (%zu bins%s), tiles %.1f s, mesh %.1f s, total %.1f s; "
      "peak memory %.2f GB\n"
      "  on disk: tiles %.1f bytes per point (%.2f GB), mesh file %s %.1f "
      "bytes per point (%.2f GB)\n",
      f.out.c_str(), static_cast<unsigned long long>(manifest.input_points),
      static_cast<unsigned long long>(manifest.vertices), manifest.tiles.size(),
      stats.tiles_reused, static_cast<unsigned long long>(triangles),
      stats.bin_seconds, stats.bins, stats.bins_reused ? ", kept" : "",
      stats.tile_seconds, stats.mesh_seconds, manifest.build_seconds,
      usage.ru_maxrss * 1024.0 / 1e9, tile_bytes / vertices, tile_bytes / 1e9,
      manifest.mesh_file.c_str(), mesh_bytes / vertices, mesh_bytes / 1e9);
  return 0;
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) { return locator::Run(argc, argv); }
