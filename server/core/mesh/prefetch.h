// Prefetch(): a cache hint the compiler must keep.
//
// __builtin_prefetch has no effect the compiler can see, so GCC deems a
// function whose only effects are prefetches pure and deletes calls to it
// whose result is unused: a look-ahead that prefetches for the next query
// silently vanishes. The empty volatile asm taking the address is an effect
// it must keep; it emits no instruction and clobbers nothing.

#ifndef LOCATOR_CORE_PREFETCH_H_
#define LOCATOR_CORE_PREFETCH_H_

namespace locator {

// A hint that the cache line at p is about to be read.
inline void Prefetch(const void* p) {
  __builtin_prefetch(p);
  asm volatile("" : : "r"(p));
}

}  // namespace locator

#endif  // LOCATOR_CORE_PREFETCH_H_
