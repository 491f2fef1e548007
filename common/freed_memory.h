// ReturnFreedMemory: gives the pages of freed heap blocks back to the
// system. glibc's malloc keeps what a thread freed in its arena for reuse,
// so after a large transient allocation (a triangulation's build, a large
// HTTP reply) the process would stay at its peak resident size.
//
// A no-op under AddressSanitizer and ThreadSanitizer: they replace malloc,
// glibc's arenas then stay uninitialised, and malloc_trim() would set them
// up unsynchronised, racing another thread's call (a crash seen under ASAN
// with two datasets built at once).
//
// Thread-safety: may be called from any thread.

#ifndef LOCATOR_COMMON_FREED_MEMORY_H_
#define LOCATOR_COMMON_FREED_MEMORY_H_

namespace locator {

// Returns the pages of freed blocks to the system (glibc's malloc only).
void ReturnFreedMemory();

}  // namespace locator

#endif  // LOCATOR_COMMON_FREED_MEMORY_H_
