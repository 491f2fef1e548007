// libFuzzer target: arbitrary bytes as a mesh file (locatord --mesh-cache).
// Decoding must reject them with a Status, or yield a mesh that passes the
// structural checks and on which every face can be described and a start
// found, without a crash, a leak or undefined behaviour.
//
// Seeds: tests/fuzz/corpus/mesh_file_fuzzer/ (files of the fixture's
// datasets; see tests/core/mesh/mesh_file_test.cc to regenerate them).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "server/core/mesh/mesh_check.h"
#include "server/core/mesh/mesh_file.h"
#include "tests/fuzz/mesh_file_fixture.h"

namespace {

// Decodes `bytes` as made for the fingerprint they name, then uses the mesh.
void DecodeAndUse(const std::string& bytes) {
  if (bytes.size() < locator::kMeshFileHeaderBytes) return;
  locator::ServingMesh::Arrays arrays;
  locator::MeshFacts facts;
  if (!locator::DecodeMeshFile(bytes, locator::fuzz::MeshFileFingerprint(bytes),
                               &arrays, &facts)
           .ok()) {
    return;
  }
  if (!locator::CheckMeshArrays(arrays).ok()) __builtin_trap();
  const locator::ServingMesh mesh(nullptr, arrays);
  for (uint32_t f = 0; f < mesh.num_faces() && f < 256; ++f) {
    const locator::Point2 a = mesh.CornerPoint(f, 0),
                          b = mesh.CornerPoint(f, 1),
                          c = mesh.CornerPoint(f, 2);
    const locator::Point2 centroid{(a.x + b.x + c.x) / 3,
                                   (a.y + b.y + c.y) / 3};
    locator::LocateResult result;
    mesh.Describe(f, locator::LocationType::kFace, -1, centroid, &result);
    if (mesh.TriangleNear(centroid) >= mesh.num_faces()) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  DecodeAndUse(bytes);
  // A mutation almost never keeps the length and checksums right; a
  // resealed copy reaches the layout and structure checks behind them.
  if (bytes.size() >= locator::kMeshFileHeaderBytes) {
    locator::fuzz::ResealMeshFile(&bytes,
                                  locator::fuzz::MeshFileFingerprint(bytes));
    DecodeAndUse(bytes);
  }
  return 0;
}
