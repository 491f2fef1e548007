// What the mesh file fuzzer, its seed corpus (tests/fuzz/corpus/
// mesh_file_fuzzer/) and the core tests share: a small holed dataset with
// breaklines and values, whose mesh files the seeds are, and the resealing
// that lets a mutated file reach the checks behind its checksums.
//
// Header-only, so that the fuzz target needs no support library.
// Thread-safety: plain functions.

#ifndef LOCATOR_TESTS_FUZZ_MESH_FILE_FIXTURE_H_
#define LOCATOR_TESTS_FUZZ_MESH_FILE_FIXTURE_H_

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/dataset/dataset_fingerprint.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/mesh_file.h"

namespace locator::fuzz {

// 60 uniform points (and a repeat of the first) with values, inside a square
// ring with a square hole, crossed by a breakline.
inline Dataset MeshFileFixtureDataset() {
  const auto height = [](const Point2& p) { return 3 * p.x - p.y; };
  const auto line = [&height](std::vector<Point2> points) {
    Polyline l{std::move(points), {}};
    for (const Point2& p : l.points) l.values.push_back(height(p));
    return l;
  };
  Dataset d = GenerateUniform(60, 7);
  d.points.push_back(d.points[0]);  // merged into point 0
  for (const Point2& p : d.points) d.values.push_back(height(p));
  d.constraints.rings.push_back(
      line({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}));
  d.constraints.rings.push_back(
      line({{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}));
  d.constraints.breaklines.push_back(line({{0.2, 0.2}, {0.8, 0.3}}));
  return d;
}

// Header fields the resealing rewrites (offsets of mesh_file.cc's Header).
inline constexpr size_t kMeshFingerprintAt = 16;
inline constexpr size_t kMeshFileBytesAt = 24;
inline constexpr size_t kMeshPayloadChecksumAt = 168;
inline constexpr size_t kMeshHeaderChecksumAt = 248;

inline void PutU64(std::string* bytes, size_t at, uint64_t value) {
  std::memcpy(bytes->data() + at, &value, sizeof(value));
}

// The fingerprint field of a file at least kMeshFileHeaderBytes long.
inline uint64_t MeshFileFingerprint(const std::string& bytes) {
  uint64_t value;
  std::memcpy(&value, bytes.data() + kMeshFingerprintAt, sizeof(value));
  return value;
}

// Makes the length field, the payload checksum and the header checksum of
// a mesh file agree with its bytes, and its fingerprint `fingerprint`, so
// that a mutated file reaches the layout and structure checks.
inline void ResealMeshFile(std::string* bytes, uint64_t fingerprint) {
  if (bytes->size() < kMeshFileHeaderBytes) return;
  PutU64(bytes, kMeshFingerprintAt, fingerprint);
  PutU64(bytes, kMeshFileBytesAt, bytes->size());
  const std::string_view file(*bytes);
  PutU64(bytes, kMeshPayloadChecksumAt,
         Xxh3Of(file.substr(kMeshFileHeaderBytes)));
  PutU64(bytes, kMeshHeaderChecksumAt,
         Xxh3Of(file.substr(0, kMeshHeaderChecksumAt)));
}

}  // namespace locator::fuzz

#endif  // LOCATOR_TESTS_FUZZ_MESH_FILE_FIXTURE_H_
