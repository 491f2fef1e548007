// SortByHighHalf: a stable LSD radix sort of 64-bit items by their upper 32
// bits (a key), for the large sorts of the builds where the lower half is an
// index: the tiled build's (points by Hilbert key, triangles by centroid
// key) and a grid TIN's (vertices and triangles in row-major order).
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_MESH_RADIX_SORT_H_
#define LOCATOR_CORE_MESH_RADIX_SORT_H_

#include <cstdint>
#include <vector>

#include "server/core/mesh/large_vector.h"

namespace locator {

// Sorts `items` by item >> 32, keeping the order of equal keys: two passes
// of 16 bits, O(n + 2^16).
inline void SortByHighHalf(LargeVector<uint64_t>* items) {
  LargeVector<uint64_t> buffer(items->size());
  for (const int shift : {32, 48}) {
    std::vector<uint32_t> start(65537, 0);
    for (const uint64_t item : *items) ++start[((item >> shift) & 0xffff) + 1];
    for (size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    for (const uint64_t item : *items) {
      buffer[start[(item >> shift) & 0xffff]++] = item;
    }
    items->swap(buffer);
  }
}

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_RADIX_SORT_H_
