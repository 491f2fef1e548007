// Fnv1a64: the 64-bit FNV-1a hash, fed incrementally. The tuning state uses
// it twice: as the digest of a dataset's vertices (its fingerprint) and as
// the checksum of a state file. Integers and doubles are fed as their
// little-endian bytes, so a digest means the same on every platform.
//
// Thread-safety: a plain value; one instance per thread.

#ifndef LOCATOR_CORE_FNV_HASH_H_
#define LOCATOR_CORE_FNV_HASH_H_

#include <bit>
#include <cstdint>
#include <string_view>

namespace locator {

class Fnv1a64 {
 public:
  // Feeds `bytes`.
  void Add(std::string_view bytes) {
    for (const char c : bytes) {
      hash_ ^= static_cast<unsigned char>(c);
      hash_ *= kPrime;
    }
  }
  // Feeds the 8 little-endian bytes of `value`.
  void AddU64(uint64_t value) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (value >> (8 * i)) & 0xff;
      hash_ *= kPrime;
    }
  }
  // Feeds the IEEE-754 bits of `value`.
  void AddDouble(double value) { AddU64(std::bit_cast<uint64_t>(value)); }

  uint64_t digest() const { return hash_; }

 private:
  static constexpr uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
  static constexpr uint64_t kPrime = 0x100000001b3ull;

  uint64_t hash_ = kOffsetBasis;
};

}  // namespace locator

#endif  // LOCATOR_CORE_FNV_HASH_H_
