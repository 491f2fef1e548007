#include "tests/testing/process_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace locator::test {
namespace {

// Field `name` ("VmRSS") of /proc/PID/status, which it gives in kB.
uint64_t StatusBytes(pid_t pid, const std::string& name) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  const std::string prefix = name + ":";
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::istringstream fields(line.substr(prefix.size()));
    uint64_t kib = 0;
    fields >> kib;
    return kib * 1024;
  }
  return 0;
}

}  // namespace

uint64_t ResidentBytes(pid_t pid) { return StatusBytes(pid, "VmRSS"); }

uint64_t PeakResidentBytes(pid_t pid) { return StatusBytes(pid, "VmHWM"); }

}  // namespace locator::test
