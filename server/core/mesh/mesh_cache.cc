#include "server/core/mesh/mesh_cache.h"

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <utility>

#include "common/freed_memory.h"
#include "common/status_macros.h"
#include "server/core/cgal/given_mesh.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/dataset/dataset_fingerprint.h"
#include "server/core/dataset/file_io.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/tiling/tiled_build.h"

namespace locator {
namespace {

std::string GeneratedKeyPath(const std::string& dir,
                             const GeneratorSpec& spec) {
  return DigestNamedPath(dir, "generated-", Xxh3Of(spec.CanonicalKey()),
                         ".key");
}

}  // namespace

std::string MeshFilePath(const std::string& dir, uint64_t fingerprint) {
  return DigestNamedPath(dir, "mesh-", fingerprint, ".mesh");
}

StatusOr<BuiltMesh> TriangulateMesh(const Dataset& dataset, unsigned threads) {
  // A mesh served as given needs no constraint hierarchy.
  if (IsGivenMesh(dataset)) return BuildGivenMesh(dataset);
  BuiltMesh built;
  if (dataset.constraints.empty()) {
    TiledBuildOptions options;
    options.threads = threads;
    const Status s =
        BuildTiledMesh(dataset.points, dataset.values, options, &built);
    // The tiles' CGAL triangulations were many small blocks, now freed.
    ReturnFreedMemory();
    RETURN_IF_ERROR(s);
    return built;
  }
  ASSIGN_OR_RETURN(std::unique_ptr<Triangulation> t,
                   Triangulation::Build(dataset));
  built.mesh = t->shared_mesh();
  built.facts.constraints = t->num_constraints();
  built.facts.holes = t->num_holes();
  built.facts.duplicates_merged = t->duplicates_merged();
  built.facts.outline = OutlineOf(*t, kOutlineSize);
  built.facts.edge_sample = built.mesh->SampleEdges(kEdgeSampleSize);
  // The engine serves from the mesh alone. CGAL's faces and vertices are
  // many small blocks that malloc keeps after they are freed; trimming
  // returns their pages, so the process shrinks to about the mesh.
  t.reset();
  ReturnFreedMemory();
  return built;
}

Status MapCachedMesh(const std::string& cache_dir, uint64_t fingerprint,
                     BuiltMesh* out, MeshCacheOutcome* outcome) {
  *outcome = MeshCacheOutcome();
  outcome->fingerprint = fingerprint;
  outcome->path = MeshFilePath(cache_dir, fingerprint);
  StatusOr<BuiltMesh> mapped = MapMeshFile(outcome->path, fingerprint);
  outcome->mapped = mapped.ok();
  if (!mapped.ok()) {
    if (mapped.status().code() != Status::Code::kNotFound) {
      outcome->load_error = mapped.status().message();
    }
    return std::move(mapped).status();
  }
  *out = std::move(mapped).value();
  return Status::OK();
}

Status BuildOrMapMesh(const Dataset& dataset, const std::string& cache_dir,
                      BuiltMesh* out, MeshCacheOutcome* outcome,
                      unsigned build_threads) {
  *outcome = MeshCacheOutcome();
  if (cache_dir.empty()) {
    ASSIGN_OR_RETURN(*out, TriangulateMesh(dataset, build_threads));
    return Status::OK();
  }
  const uint64_t fingerprint = DatasetFingerprint(dataset);
  if (MapCachedMesh(cache_dir, fingerprint, out, outcome).ok()) {
    return Status::OK();
  }
  ASSIGN_OR_RETURN(*out, TriangulateMesh(dataset, build_threads));
  if (const Status saved = WriteMeshFile(outcome->path, fingerprint, *out);
      !saved.ok()) {
    outcome->save_error = saved.message();
  }
  return Status::OK();
}

Status FindGeneratedFingerprint(const std::string& cache_dir,
                                const GeneratorSpec& spec,
                                uint64_t* fingerprint) {
  const std::string path = GeneratedKeyPath(cache_dir, spec);
  std::string text;
  RETURN_IF_ERROR(ReadWholeFile(path, "generated dataset key", &text, 64));
  char* end = nullptr;
  errno = 0;
  const uint64_t value = std::strtoull(text.c_str(), &end, 16);
  if (text.size() != 17 || errno != 0 || end != text.c_str() + 16 ||
      *end != '\n') {
    return Status::InvalidArgument("generated dataset key " + path +
                                   " is not 16 hex digits and a newline");
  }
  *fingerprint = value;
  return Status::OK();
}

Status RecordGeneratedFingerprint(const std::string& cache_dir,
                                  const GeneratorSpec& spec,
                                  uint64_t fingerprint) {
  char text[18];
  std::snprintf(text, sizeof(text), "%016" PRIx64 "\n", fingerprint);
  return WriteFileAtomically(GeneratedKeyPath(cache_dir, spec),
                             std::string_view(text, 17));
}

}  // namespace locator
