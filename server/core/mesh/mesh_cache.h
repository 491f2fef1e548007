// The serving mesh of a dataset, triangulated or mapped from a mesh cache:
// a directory of mesh files (mesh_file.h) named after the fingerprint of
// the dataset each was built from ("mesh-<16 hex digits>.mesh"), so that
// the meshes of several datasets sit side by side and a restart, a reload
// or another replica on the host maps the file instead of triangulating.
//
// Thread-safety: free functions. Processes and threads may share a cache
// directory: files are written atomically (the last rename wins whole), and
// a mapping keeps the file it mapped even when a newer one replaces it.

#ifndef LOCATOR_CORE_MESH_CACHE_H_
#define LOCATOR_CORE_MESH_CACHE_H_

#include <cstdint>
#include <string>

#include "locator/dataset.h"
#include "locator/dataset_sources.h"
#include "locator/engine_info.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/core/mesh/mesh_file.h"

namespace locator {

// The mesh file of the dataset with `fingerprint` in `dir`
// (DigestNamedPath: "mesh-<16 hex digits>.mesh").
std::string MeshFilePath(const std::string& dir, uint64_t fingerprint);

// Triangulates `dataset` and derives its serving mesh and facts: a mesh
// given as triangles takes BuildGivenMesh's shorter way (given_mesh.h), a
// plain point set is built in tiles on `threads` threads
// (tiling/tiled_build.h), a constrained one with CGAL, whose triangulation
// is freed. The same points give the same mesh either way. InvalidArgument
// as Triangulation::Build.
StatusOr<BuiltMesh> TriangulateMesh(const Dataset& dataset, unsigned threads);

// With an empty `cache_dir`, TriangulateMesh. Otherwise maps the dataset's
// file in `cache_dir` if it is sound; if there is none, or it is unusable
// (the reason goes to outcome->load_error), triangulates and writes the
// file (a failure goes to outcome->save_error; the mesh is served anyway).
Status BuildOrMapMesh(const Dataset& dataset, const std::string& cache_dir,
                      BuiltMesh* out, MeshCacheOutcome* outcome,
                      unsigned build_threads = 1);

// Maps the mesh file of the dataset with `fingerprint` in `cache_dir`,
// filling *outcome (mapped, or why not in load_error). NotFound if there is
// no file; IOError or InvalidArgument as MapMeshFile.
Status MapCachedMesh(const std::string& cache_dir, uint64_t fingerprint,
                     BuiltMesh* out, MeshCacheOutcome* outcome);

// Generated datasets: a start can map the mesh of a generator spec without
// generating its points first, through a key file in the cache directory,
// "generated-<16 hex digits>.key" (an XXH3 digest of the spec's
// CanonicalKey()), that holds the fingerprint of the points it generates.
// The mesh file itself is still checked against that fingerprint.

// The fingerprint recorded for `spec`; NotFound if none, InvalidArgument
// if the key file is not one.
Status FindGeneratedFingerprint(const std::string& cache_dir,
                                const GeneratorSpec& spec,
                                uint64_t* fingerprint);
// Records that `spec` generates the dataset with `fingerprint` (atomically;
// IOError naming the step that failed).
Status RecordGeneratedFingerprint(const std::string& cache_dir,
                                  const GeneratorSpec& spec,
                                  uint64_t fingerprint);

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_CACHE_H_
