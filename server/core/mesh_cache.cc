#include "server/core/mesh_cache.h"

#include <malloc.h>

#include <cinttypes>
#include <cstdio>
#include <memory>
#include <utility>

#include "server/core/dataset_fingerprint.h"
#include "server/core/triangulation.h"

namespace locator {
namespace {

std::string MeshFilePath(const std::string& dir, uint64_t fingerprint) {
  char name[32];
  std::snprintf(name, sizeof(name), "mesh-%016" PRIx64 ".mesh", fingerprint);
  return dir + "/" + name;
}

}  // namespace

Status TriangulateMesh(const Dataset& dataset, BuiltMesh* out) {
  std::unique_ptr<Triangulation> t;
  if (Status s = Triangulation::Build(dataset, &t); !s.ok()) return s;
  out->mesh = t->shared_mesh();
  out->facts.constraints = t->num_constraints();
  out->facts.holes = t->num_holes();
  out->facts.outline = OutlineOf(*t, MeshFacts::kOutlineSize);
  out->facts.edge_sample = out->mesh->SampleEdges(MeshFacts::kEdgeSampleSize);
  // The engine serves from the mesh alone. CGAL's faces and vertices are
  // many small blocks that malloc keeps after they are freed; trimming
  // returns their pages, so the process shrinks to about the mesh.
  t.reset();
  malloc_trim(0);
  return Status::OK();
}

Status BuildOrMapMesh(const Dataset& dataset, const std::string& cache_dir,
                      BuiltMesh* out, MeshCacheOutcome* outcome) {
  *outcome = MeshCacheOutcome();
  if (cache_dir.empty()) return TriangulateMesh(dataset, out);
  const uint64_t fingerprint = DatasetFingerprint(dataset);
  outcome->path = MeshFilePath(cache_dir, fingerprint);
  Status status = MapMeshFile(outcome->path, fingerprint, out);
  if (status.ok()) {
    outcome->mapped = true;
    return status;
  }
  if (status.code() != Status::Code::kNotFound) {
    outcome->load_error = status.message();
  }
  if (status = TriangulateMesh(dataset, out); !status.ok()) return status;
  if (Status saved = WriteMeshFile(outcome->path, fingerprint, *out);
      !saved.ok()) {
    outcome->save_error = saved.message();
  }
  return Status::OK();
}

}  // namespace locator
