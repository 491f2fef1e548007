// ThreadRandom: cheap per-thread random bits (xorshift64) for the hot path.
//
// Walk edge order and jump-and-walk sampling need a few random bits per
// query; a thread-local state keeps concurrent queries independent without
// locking. The sequence is fixed per thread, so single-threaded benchmarks
// are reproducible.

#ifndef LOCATOR_CORE_FAST_RANDOM_H_
#define LOCATOR_CORE_FAST_RANDOM_H_

#include <cstdint>

namespace locator {

inline uint64_t ThreadRandom() {
  thread_local uint64_t state = 0x9E3779B97F4A7C15ull;
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return state;
}

}  // namespace locator

#endif  // LOCATOR_CORE_FAST_RANDOM_H_
