// ProcessStatusBytes: a byte count of this process from /proc/self/status
// (VmRSS, VmHWM, RssAnon, RssFile ...), for the benchmarks' memory figures.
//
// Thread-safety: a free function.

#ifndef LOCATOR_SERVER_BENCH_PROCESS_STATUS_H_
#define LOCATOR_SERVER_BENCH_PROCESS_STATUS_H_

#include <cstddef>
#include <fstream>
#include <string>

namespace locator::bench {

// The "<field>" line of /proc/self/status (e.g. "VmRSS:"), in bytes; 0 if
// there is none.
inline size_t ProcessStatusBytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(field, 0) == 0) {
      return std::stoull(line.substr(field.size())) * 1024;
    }
  }
  return 0;
}

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_PROCESS_STATUS_H_
