// Mesh files: a serving mesh (serving_mesh.h) and what the engine derived
// with it from CGAL's triangulation, stored so that a later start maps the
// file instead of triangulating (locatord --mesh-cache).
//
// Layout (little-endian, native doubles; every section starts at a multiple
// of 64 bytes, so a mapped file's arrays are aligned):
//   header     256 bytes: magic "locmesh\0", format version, byte-order
//              mark, the dataset fingerprint the mesh was built from, the
//              file's length, every section's element count, the dataset
//              facts (input points, digest, constraints, holes, duplicates
//              merged, bounding box), an XXH3-64 checksum of everything after
//              the header, and last an XXH3-64 checksum of the header's other
//              bytes.
//   sections   triangles (24 B each), points (16 B), values (8 B, none
//              without values), public ids (4 B), hull edges (4 B), then the
//              domain outline's boundary and breakline segments and the edge
//              sample (32 B per segment).
//
// A file is used only when all of these hold, each failure naming itself:
// the magic, byte order and version match; the header's checksum matches;
// it was made for the expected fingerprint; its length is what the counts
// say; the payload's checksum matches; and every index in it stays inside
// the arrays, every triangle is strictly counter-clockwise and every
// coordinate finite (CheckMeshArrays). The
// checksums and the fingerprint vouch that the mesh is the triangulation a
// build of that dataset wrote; the bounds checks make sure that no bytes,
// however made, lead a query outside the arrays.
//
// Bump kMeshFileVersion whenever the layout or the way a mesh is derived
// from a dataset changes (vertex or triangle order included).
//
// Thread-safety: free functions.

#ifndef LOCATOR_CORE_MESH_FILE_H_
#define LOCATOR_CORE_MESH_FILE_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/core/cgal/domain_outline.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// 2: corners rotated to the smallest id first, the hull ring from the edge
// ending at the smallest id, ties in the triangle order by rotated ids.
// 3: the dataset digest in the header is XXH3 (Triangulation::VertexDigest;
// it was FNV-1a).
inline constexpr uint32_t kMeshFileVersion = 3;
inline constexpr size_t kMeshFileHeaderBytes = 256;

// What the engine keeps of a triangulation besides its serving mesh.
struct MeshFacts {
  uint64_t constraints = 0;        // constrained segments inserted
  uint64_t duplicates_merged = 0;  // input points equal to an earlier one
  uint64_t holes = 0;              // out-of-domain regions inside the hull
  // OutlineOf(t, kOutlineSize).
  DomainOutline outline;
  // mesh.SampleEdges(kEdgeSampleSize).
  std::vector<std::array<Point2, 2>> edge_sample;
};

// A mesh with its facts: what Engine::Create builds or maps.
struct BuiltMesh {
  std::shared_ptr<const ServingMesh> mesh;
  MeshFacts facts;
};

// Writes `built` to `path` atomically (WriteFileAtomically), recording
// `fingerprint`. IOError naming the step that failed.
Status WriteMeshFile(const std::string& path, uint64_t fingerprint,
                     const BuiltMesh& built);

// What a mesh file's header records, for a writer that streams the large
// sections from disk instead of holding a mesh (the tile-set build).
struct MeshFileSummary {
  uint64_t fingerprint = 0;
  // Element counts of the sections, in file order.
  uint64_t triangles = 0, points = 0, values = 0, ids = 0, hull = 0;
  uint64_t boundary = 0, breaklines = 0, edge_sample = 0;
  uint64_t in_domain = 0;
  uint64_t input_points = 0;
  uint64_t digest = 0;
  uint64_t constraints = 0, holes = 0, duplicates_merged = 0;
  BoundingBox box;
};
// Where the sections of a file with a summary's counts start (in file
// order: triangles, points, values, ids, hull, boundary, breaklines, edge
// sample; zero bytes pad the gaps), and the file's length.
struct MeshFileSections {
  uint64_t start[8];
  uint64_t end;
};
MeshFileSections MeshFileSectionsOf(const MeshFileSummary& summary);
// InvalidArgument if a count is past what a mesh file holds.
Status CheckMeshFileCounts(const MeshFileSummary& summary);
// The kMeshFileHeaderBytes header of a file with `summary`, whose bytes
// after the header have the XXH3-64 digest `payload_checksum`.
std::string MeshFileHeader(const MeshFileSummary& summary,
                           uint64_t payload_checksum);

// Checks `bytes` (a whole mesh file) as described above and, if it holds a
// mesh built for `fingerprint`, points *arrays into `bytes` and fills
// *facts. InvalidArgument naming the first check that failed.
Status DecodeMeshFile(std::string_view bytes, uint64_t fingerprint,
                      ServingMesh::Arrays* arrays, MeshFacts* facts);

// Maps the mesh file at `path` (shared with every process mapping it) and
// decodes it; the mesh keeps the mapping. NotFound if there is no file;
// IOError if it cannot be mapped; InvalidArgument as DecodeMeshFile.
//
// Checked once: the first map reads the whole file and checks all of it
// (DecodeMeshFile), then records that in a stamp beside it,
// "<path>.checked": the file's device, inode, size and modification time.
// A later map of the file the stamp describes checks its header and layout
// only and leaves its pages to be read as queries touch them, so that a
// restart of a mesh far larger than RAM is ready at once. A file is
// stamped only once its modification time is a second old, so that any
// later write gives it another one.
StatusOr<BuiltMesh> MapMeshFile(const std::string& path, uint64_t fingerprint);

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_FILE_H_
