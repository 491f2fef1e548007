// Xxh3Digest: the core's one hash, a 64-bit XXH3 digest fed piecewise. The
// dataset fingerprint, the vertex digest of a mesh, the mesh file's and the
// tuning state's checksums and the names of cache files are all XXH3.
// Integers and doubles fed through AddU64/AddDouble go in as their
// little-endian bytes, so such a digest means the same on every platform.
//
// Owns its XXH3 streaming state (on the stack, no allocation).
// Thread-safety: a plain value; one instance per thread.

#ifndef LOCATOR_CORE_XXH3_DIGEST_H_
#define LOCATOR_CORE_XXH3_DIGEST_H_

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace locator {

class Xxh3Digest {
 public:
  Xxh3Digest() { XXH3_64bits_reset(&state_); }
  Xxh3Digest(const Xxh3Digest&) = delete;
  Xxh3Digest& operator=(const Xxh3Digest&) = delete;

  // Feeds the `size` bytes at `data`.
  void Add(const void* data, size_t size) {
    XXH3_64bits_update(&state_, data, size);
  }
  // Feeds `bytes`.
  void Add(std::string_view bytes) { Add(bytes.data(), bytes.size()); }
  // Feeds the 8 little-endian bytes of `value`.
  void AddU64(uint64_t value) {
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i)
      bytes[i] = static_cast<unsigned char>(value >> (8 * i));
    Add(bytes, sizeof(bytes));
  }
  // Feeds the IEEE-754 bits of `value`, little-endian.
  void AddDouble(double value) { AddU64(std::bit_cast<uint64_t>(value)); }

  // The digest of everything fed so far (more may be fed afterwards).
  uint64_t digest() const { return XXH3_64bits_digest(&state_); }

 private:
  XXH3_state_t state_;
};

// The XXH3 digest of `bytes` in one go (equal to feeding them to an
// Xxh3Digest).
inline uint64_t Xxh3Of(std::string_view bytes) {
  return XXH3_64bits(bytes.data(), bytes.size());
}

}  // namespace locator

#endif  // LOCATOR_CORE_XXH3_DIGEST_H_
