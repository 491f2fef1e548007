// Deterministic mapping of raw generator output to doubles.
//
// std::uniform_real_distribution is implementation-defined, so the same seed
// would give different datasets and query streams on different standard
// libraries. std::mt19937_64's output sequence is fixed by the standard; these
// helpers map it to doubles the same way everywhere.
//
// Thread-safety: stateless functions; the caller owns the generator.

#ifndef LOCATOR_COMMON_RANDOM_H_
#define LOCATOR_COMMON_RANDOM_H_

#include <cstddef>
#include <random>

namespace locator {

// A double uniform in [0, 1): the top 53 bits of one draw, so every value is
// an exact multiple of 2^-53.
inline double UnitDouble(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// A double uniform in [lo, hi) (for lo < hi; rounding may reach hi).
inline double UniformDouble(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * UnitDouble(rng);
}

// An index uniform in [0, n), for n >= 1: one UnitDouble() draw scaled to n
// (clamped, as the product may round up to n).
inline size_t UniformIndex(std::mt19937_64& rng, size_t n) {
  const auto i = static_cast<size_t>(UnitDouble(rng) * static_cast<double>(n));
  return i < n ? i : n - 1;
}

}  // namespace locator

#endif  // LOCATOR_COMMON_RANDOM_H_
