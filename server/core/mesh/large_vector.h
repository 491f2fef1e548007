// LargeVector: std::vector for the big arrays of a build (the tiled
// build's points, ids, triangles and sort keys; greedy insertion's mesh,
// queue and candidates), with an allocator that
//  - backs buffers of 2 MiB or more with transparent huge pages
//    (madvise(MADV_HUGEPAGE) on 2 MiB aligned memory): touching fresh
//    memory costs a page fault per 4 KiB page otherwise, hundreds of
//    thousands for 10^6 points, each a trap in a virtual machine;
//  - leaves elements that resize() adds uninitialised (default-initialised),
//    as every builder writes each element before reading it: zeroing
//    arrays of tens of megabytes first is wasted.
//
// Thread-safety: as std::allocator.

#ifndef LOCATOR_CORE_MESH_LARGE_VECTOR_H_
#define LOCATOR_CORE_MESH_LARGE_VECTOR_H_

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

namespace locator {

template <class T>
class LargeAllocator {
 public:
  using value_type = T;

  LargeAllocator() = default;
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) {}

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return std::allocator<T>().allocate(n);
    const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p == nullptr) throw std::bad_alloc();
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: failure changes nothing
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t n) {
    if (n * sizeof(T) < kHugePage) {
      std::allocator<T>().deallocate(p, n);
    } else {
      std::free(p);
    }
  }

  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  friend bool operator==(const LargeAllocator&, const LargeAllocator&) {
    return true;
  }

 private:
  static constexpr size_t kHugePage = size_t{2} << 20;
};

template <class T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_LARGE_VECTOR_H_
