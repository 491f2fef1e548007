// DecodeWithNode: quantized-mesh tiles decoded by an implementation that is
// not locator's: @here/quantized-mesh-decoder, run by node
// (tests/server/tiles/quantized_mesh_decoder/decode_tiles.js, installed by
// deploy/install-deps.sh with npm ci). A machine without node or the
// package fails the test that asks, saying what to install: it never
// skips.

#ifndef LOCATOR_TESTS_SERVER_TILES_QUANTIZED_MESH_NODE_DECODER_H_
#define LOCATOR_TESTS_SERVER_TILES_QUANTIZED_MESH_NODE_DECODER_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "locator/status.h"

namespace locator::test {

// What the decoder read from one tile.
struct DecodedTile {
  std::array<double, 3> centre;
  double min_height = 0, max_height = 0;
  std::array<double, 3> sphere_centre;
  double sphere_radius = 0;
  std::array<double, 3> occlusion;
  std::vector<std::array<uint32_t, 3>> vertices;  // u, v, height: 0..32767
  std::vector<std::array<uint32_t, 3>> triangles;
  // West, south, east and north edge indices, as the file lists them.
  std::array<std::vector<uint32_t>, 4> edges;

  // The height of vertex i in metres, dequantized as Cesium does.
  double Height(size_t i) const {
    return min_height + vertices[i][2] * (max_height - min_height) / 32767.0;
  }
};

// Decodes each of `files` (paths of .terrain files) into `tiles`, in order;
// FailedPrecondition saying what to install if node or the package is
// missing, Internal with node's output if the decoder fails.
Status DecodeWithNode(const std::vector<std::string>& files,
                      std::vector<DecodedTile>* tiles);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_TILES_QUANTIZED_MESH_NODE_DECODER_H_
