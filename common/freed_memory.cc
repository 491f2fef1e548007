#include "common/freed_memory.h"

#include <malloc.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define LOCATOR_MALLOC_REPLACED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define LOCATOR_MALLOC_REPLACED 1
#endif

namespace locator {

void ReturnFreedMemory() {
#ifndef LOCATOR_MALLOC_REPLACED
  malloc_trim(0);
#endif
}

}  // namespace locator
