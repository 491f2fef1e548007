// RunBinary: runs a program to completion for end-to-end tests and captures
// its exit code, stdout and stderr.
//
// The child's output goes to temporary files (not pipes), so a chatty child
// can never block on a full pipe. A child still running at the timeout is
// killed and reported with exit code -1.
//
// Thread-safety: a free function; each call has its own files.

#ifndef LOCATOR_TESTS_TESTING_RUN_BINARY_H_
#define LOCATOR_TESTS_TESTING_RUN_BINARY_H_

#include <chrono>
#include <string>
#include <vector>

namespace locator::test {

struct BinaryResult {
  int exit_code = -1;  // 128 + N if signal N ended it; -1 on timeout
  std::string out;
  std::string err;
};

// Runs `binary` with `args` (argv[0] is added) and waits for it.
BinaryResult RunBinary(const std::string& binary,
                       const std::vector<std::string>& args,
                       std::chrono::seconds timeout = std::chrono::seconds(60));

}  // namespace locator::test

#endif  // LOCATOR_TESTS_TESTING_RUN_BINARY_H_
