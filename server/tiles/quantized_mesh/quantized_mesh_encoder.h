// EncodeQuantizedMesh: a triangulated terrain tile as Cesium's
// quantized-mesh-1.0 bytes (github.com/CesiumGS/quantized-mesh), without
// extensions:
//
//   header       centre (ECEF), min and max height, bounding sphere,
//                horizon occlusion point (wgs84.h), little-endian
//   vertices     count, then u, v and height, each 0..32767 across the
//                tile's box and height range, zig-zag delta encoded
//   triangles    count, then indices (16 bits, 32 above 65536 vertices,
//                aligned), high-water-mark encoded: vertices are numbered
//                in the order the triangles first use them
//   edges        the vertices on the west, south, east and north sides
//                (by ClippedMesh::sides, so exactly 0 or 32767), each list
//                sorted along its side
//
// The header is computed from the positions a decoder will see (u, v and
// height dequantized), so the sphere holds every decoded vertex. The
// heights are quantized against the header's float min and max, rounded
// outwards, so none is clamped.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_SERVER_TILES_QUANTIZED_MESH_QUANTIZED_MESH_ENCODER_H_
#define LOCATOR_SERVER_TILES_QUANTIZED_MESH_QUANTIZED_MESH_ENCODER_H_

#include <string>

#include "locator/geometry.h"
#include "server/core/patch/clipped_mesh.h"

namespace locator {

// The largest quantized coordinate: u, v and height are in 0..kQuantizedMax.
inline constexpr int kQuantizedMax = 32767;

// The quantized-mesh of `mesh`, whose points are longitudes and latitudes
// (degrees) inside `box`, the tile's, and whose heights are metres above
// the ellipsoid. A mesh without triangles is a tile without vertices,
// its header at the box's centre on the ellipsoid.
std::string EncodeQuantizedMesh(const ClippedMesh& mesh,
                                const BoundingBox& box);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_QUANTIZED_MESH_QUANTIZED_MESH_ENCODER_H_
