// The memory /proc reports for a process, for the tests that bound what a
// server keeps (a flood of unread streams, a large HTTP reply, hostile
// calls). Only a server built without a sanitizer shows it: sanitizer
// allocators keep freed memory resident.
//
// Thread-safety: free functions.

#ifndef LOCATOR_TESTS_TESTING_PROCESS_MEMORY_H_
#define LOCATOR_TESTS_TESTING_PROCESS_MEMORY_H_

#include <sys/types.h>

#include <cstdint>

namespace locator::test {

// The resident set (VmRSS) of process `pid` in bytes; 0 if /proc does not
// say (no such process).
uint64_t ResidentBytes(pid_t pid);

// The peak resident set (VmHWM) of process `pid` in bytes; 0 likewise.
uint64_t PeakResidentBytes(pid_t pid);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_TESTING_PROCESS_MEMORY_H_
