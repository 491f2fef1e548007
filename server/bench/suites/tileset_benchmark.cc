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
#include "server/core/dataset/generated_points.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/core/mesh/mesh_check.h"
#include "server/core/mesh/mesh_file.h"
#include "server/core/tileset/tileset_manifest.h"
#include "server/core/tiling/tiled_build.h"

namespace locator::bench {
namespace {

// Asks the kernel to drop the cached pages of `path` (none of it mapped).
void DropFromPageCache(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
  ::close(fd);
}

// Mean ns per Locate() over `queries`, one at a time.
StatusOr<double> NsPerLocate(const Engine& engine,
                             const std::vector<Point2>& queries) {
  LocateResult result;
  const Stopwatch watch;
  for (const Point2& q : queries) RETURN_IF_ERROR(engine.Locate(q, &result));
  return watch.Seconds() * 1e9 / static_cast<double>(queries.size());
}

// Untimed passes of a workload before the timed one: the tuner plans for
// the traffic after 2000 queries and builds its table a few starts per
// query, so the first passes time the build (and, on a tile set, the page
// faults that bring the region in).
constexpr int kSettlingPasses = 5;

// Untimed passes of the hot region's queries (the 1-cluster workload over
// `box`), then the timed one.
StatusOr<double> HotRegionNs(const Engine& engine, const BoundingBox& box,
                             size_t count) {
  for (int pass = 0; pass < kSettlingPasses; ++pass) {
    RETURN_IF_ERROR(
        NsPerLocate(engine, WorkloadQueries(WorkloadKind::kOneCluster, box,
                                            count, 10 + pass))
            .status());
  }
  return NsPerLocate(engine,
                     WorkloadQueries(WorkloadKind::kOneCluster, box, count, 2));
}

// The points of the generator spec `source` in the part of `box` around
// the 1-cluster square (its middle 0.08 x 0.08: the square and as much
// again around it), streamed, for the same region in RAM.
StatusOr<Dataset> HotRegionPoints(const std::string& source,
                                  const BoundingBox& box) {
  ASSIGN_OR_RETURN(const GeneratorSpec spec, ParseGeneratorSpec(source));
  const auto at = [](double lo, double hi, double f) {
    return lo + (hi - lo) * f;
  };
  const BoundingBox region{
      at(box.min_x, box.max_x, 0.46), at(box.min_y, box.max_y, 0.46),
      at(box.min_x, box.max_x, 0.54), at(box.min_y, box.max_y, 0.54)};
  Dataset dataset;
  GeneratedPoints points(spec);
  for (size_t i = 0; i < spec.n; ++i) {
    const Point2 p = points.Next();
    if (p.x >= region.min_x && p.x <= region.max_x && p.y >= region.min_y &&
        p.y <= region.max_y) {
      dataset.points.push_back(p);
    }
  }
  return dataset;
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

// The tile set's engine against one built in memory from its source (a
// generator), on `count` uniform queries: answers that differ (type,
// triangle, vertices), and whether the mesh arrays are the same bytes.
Status VerifyAgainstMemory(const Engine& tiled, const std::string& mesh_path,
                           const TileSetManifestSummary& manifest, size_t count,
                           Table* table) {
  ASSIGN_OR_RETURN(
      Dataset dataset,
      LoadDataset(manifest.source, DatasetLimits{ServingMesh::kMaxElements}));
  BuiltMesh built;
  TiledBuildOptions build;
  build.threads = 2;
  RETURN_IF_ERROR(
      BuildTiledMesh(dataset.points, dataset.values, build, &built));
  ASSIGN_OR_RETURN(const BuiltMesh mapped,
                   MapMeshFile(mesh_path, manifest.fingerprint));
  const Status same =
      CompareMeshArrays(mapped.mesh->arrays(), built.mesh->arrays());
  table->Row("verify: mesh arrays identical to the build in memory (1 = yes)",
             same.ok() ? 1 : 0, "");
  ASSIGN_OR_RETURN(std::unique_ptr<Engine> in_memory,
                   Engine::Create(std::move(dataset), EngineOptions()));
  const std::vector<Point2> queries = WorkloadQueries(
      WorkloadKind::kUniform, tiled.dataset_info().bounding_box, count, 4);
  std::vector<LocateResult> got, want;
  RETURN_IF_ERROR(tiled.LocateBatch(queries, &got));
  RETURN_IF_ERROR(in_memory->LocateBatch(queries, &want));
  size_t differ = 0;
  for (size_t k = 0; k < queries.size(); ++k) {
    differ += got[k].type != want[k].type ||
              got[k].triangle_id != want[k].triangle_id ||
              got[k].vertex_ids != want[k].vertex_ids;
  }
  table->Row("verify: uniform queries", static_cast<double>(count), "");
  table->Row("verify: answers that differ", static_cast<double>(differ), "");
  return same.ok() && differ == 0
             ? Status::OK()
             : Status::Internal(
                   "the tile set differs from the build in "
                   "memory");
}

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
  // Ready as locatord is: the tuner on its own thread, the engine serving
  // while the first table is built.
  DropFromPageCache(mesh_path);
  DatasetOrigin origin;
  origin.source = manifest.source;
  engine_options.tuning = options.tuning;
  engine_options.tuning.mesh_larger_than_memory = true;  // as locatord maps it
  engine_options.tuning.background = true;
  Stopwatch watch;
  ASSIGN_OR_RETURN(
      std::unique_ptr<Engine> tiled,
      Engine::CreateFromMeshFile(manifest.fingerprint, origin, engine_options));
  table.Row("tile set: cold page cache to ready", watch.Seconds(), "s");
  table.Row("tile set: points", manifest.input_points / 1e6, "M");
  table.Memory("mapping");
  tiled.reset();
  // Measured as locator-bench --scale measures: the tuner in the query
  // path, its first table built before the first query.
  engine_options.tuning.background = false;
  watch.Restart();
  ASSIGN_OR_RETURN(tiled, Engine::CreateFromMeshFile(manifest.fingerprint,
                                                     origin, engine_options));
  table.Row("tile set: ready, the tuner in the query path", watch.Seconds(),
            "s");
  table.Memory("mapping again");
  if (options.verify) {
    RETURN_IF_ERROR(VerifyAgainstMemory(*tiled, mesh_path, manifest,
                                        options.verify_queries, &table));
  }

  // The hot region first, as a server that has just started sees it.
  const BoundingBox& box = tiled->dataset_info().bounding_box;
  ASSIGN_OR_RETURN(const double hot, HotRegionNs(*tiled, box, options.queries));
  table.Row("tile set: hot region (1-cluster)", hot, "ns/locate");
  table.Row("tile set: hot region, faces per locate",
            tiled->Stats().mean_cost_recent, "");
  table.Memory("the hot region");
  const std::vector<Point2> uniform =
      WorkloadQueries(WorkloadKind::kUniform, box, options.queries, 3);
  ASSIGN_OR_RETURN(const double first, NsPerLocate(*tiled, uniform));
  table.Row("tile set: uniform, first pass (cold)", first, "ns/locate");
  for (int pass = 0; pass < kSettlingPasses; ++pass) {
    RETURN_IF_ERROR(NsPerLocate(*tiled, uniform).status());
  }
  ASSIGN_OR_RETURN(const double warm, NsPerLocate(*tiled, uniform));
  table.Row("tile set: uniform, warm (after 5 more passes)", warm, "ns/locate");
  table.Memory("the uniform passes");
  tiled.reset();

  // The same region in RAM: its points (and as many around them) built in
  // memory, the same queries.
  const Stopwatch region_watch;
  ASSIGN_OR_RETURN(Dataset region, HotRegionPoints(manifest.source, box));
  const size_t region_points = region.points.size();
  EngineOptions in_ram_options;
  in_ram_options.tuning = options.tuning;
  ASSIGN_OR_RETURN(std::unique_ptr<Engine> in_ram,
                   Engine::Create(std::move(region), in_ram_options));
  table.Row("in RAM: the hot region's points", region_points / 1e6, "M");
  ASSIGN_OR_RETURN(const double ram_hot,
                   HotRegionNs(*in_ram, box, options.queries));
  table.Row("in RAM: hot region (1-cluster)", ram_hot, "ns/locate");
  table.Row("in RAM: hot region, faces per locate",
            in_ram->Stats().mean_cost_recent, "");
  table.Row("hot region: tile set / in RAM", hot / ram_hot, "x");
  table.Memory("the region in RAM");
  return Status::OK();
}

}  // namespace locator::bench
