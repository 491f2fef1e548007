#include "server/bench/suites/tileset_benchmark.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "common/status_macros.h"
#include "common/workload.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/bench/process_status.h"
#include "server/bench/stopwatch.h"
#include "server/core/dataset/file_io.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/core/tileset/tileset_manifest.h"

namespace locator::bench {
namespace {

// Asks the kernel to drop the cached pages of `path` (none of it mapped).
void DropFromPageCache(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
  ::close(fd);
}

std::vector<Point2> Queries(WorkloadKind kind, const BoundingBox& box,
                            size_t count, uint64_t seed) {
  Workload workload(kind, box, seed);
  std::vector<Point2> queries(count);
  for (Point2& q : queries) q = workload.Next();
  return queries;
}

// Mean ns per Locate() over `queries`, one at a time.
StatusOr<double> NsPerLocate(const Engine& engine,
                             const std::vector<Point2>& queries) {
  LocateResult result;
  const Stopwatch watch;
  for (const Point2& q : queries) RETURN_IF_ERROR(engine.Locate(q, &result));
  return watch.Seconds() * 1e9 / static_cast<double>(queries.size());
}

// Untimed hot-region queries for the tuner, then the timed ones.
StatusOr<double> HotRegionNs(const Engine& engine, size_t count) {
  const BoundingBox& box = engine.dataset_info().bounding_box;
  RETURN_IF_ERROR(
      NsPerLocate(engine, Queries(WorkloadKind::kOneCluster, box, count, 1))
          .status());
  return NsPerLocate(engine, Queries(WorkloadKind::kOneCluster, box, count, 2));
}

class Table {
 public:
  explicit Table(std::ostream& out) : out_(out) {
    out_ << "| figure | value |\n|---|---|\n";
  }
  void Row(const char* what, double value, const char* unit) {
    char line[200];
    std::snprintf(line, sizeof(line), "| %s | %.3f %s |\n", what, value, unit);
    out_ << line << std::flush;
  }
  void Memory(const char* when) {
    char what[120];
    std::snprintf(what, sizeof(what), "resident after %s (anon + file)", when);
    char line[240];
    std::snprintf(line, sizeof(line), "| %s | %.2f + %.2f GB |\n", what,
                  ProcessStatusBytes("RssAnon:") / 1e9,
                  ProcessStatusBytes("RssFile:") / 1e9);
    out_ << line << std::flush;
  }

 private:
  std::ostream& out_;
};

}  // namespace

Status RunTileSet(const TileSetBenchOptions& options, std::ostream& out) {
  std::string text;
  RETURN_IF_ERROR(ReadWholeFile(options.manifest, "manifest", &text));
  TileSetManifestSummary manifest;
  RETURN_IF_ERROR(ParseManifestSummary(text, options.manifest, &manifest));
  EngineOptions engine_options;
  engine_options.mesh_cache_dir =
      std::filesystem::path(options.manifest).parent_path().string();
  const std::string mesh_path =
      MeshFilePath(engine_options.mesh_cache_dir, manifest.fingerprint);

  Table table(out);
  DropFromPageCache(mesh_path);
  Stopwatch watch;
  DatasetOrigin origin;
  origin.source = manifest.source;
  ASSIGN_OR_RETURN(
      std::unique_ptr<Engine> tiled,
      Engine::CreateFromMeshFile(manifest.fingerprint, origin, engine_options));
  table.Row("tile set: cold page cache to ready", watch.Seconds(), "s");
  table.Row("tile set: points", manifest.input_points / 1e6, "M");
  table.Memory("mapping");

  const BoundingBox& box = tiled->dataset_info().bounding_box;
  const std::vector<Point2> uniform =
      Queries(WorkloadKind::kUniform, box, options.queries, 3);
  ASSIGN_OR_RETURN(const double first, NsPerLocate(*tiled, uniform));
  table.Row("tile set: uniform, first pass", first, "ns/locate");
  ASSIGN_OR_RETURN(const double second, NsPerLocate(*tiled, uniform));
  table.Row("tile set: uniform, second pass (warm)", second, "ns/locate");
  ASSIGN_OR_RETURN(const double hot, HotRegionNs(*tiled, options.queries));
  table.Row("tile set: hot region (1-cluster)", hot, "ns/locate");
  table.Memory("the tile set's queries");
  tiled.reset();

  ASSIGN_OR_RETURN(
      Dataset dataset,
      LoadDataset(options.ram_dataset, DatasetLimits{size_t{1} << 31}));
  ASSIGN_OR_RETURN(std::unique_ptr<Engine> in_ram,
                   Engine::Create(std::move(dataset), EngineOptions()));
  ASSIGN_OR_RETURN(const double ram_hot, HotRegionNs(*in_ram, options.queries));
  table.Row(
      ("in RAM (" + options.ram_dataset + "): hot region (1-cluster)").c_str(),
      ram_hot, "ns/locate");
  table.Row("hot region: tile set / in RAM", hot / ram_hot, "x");
  table.Memory("the in-RAM dataset's queries");
  return Status::OK();
}

}  // namespace locator::bench
