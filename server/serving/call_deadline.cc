#include "server/serving/call_deadline.h"

#include <string>

namespace locator {

CallDeadline CallDeadline::ServerDefault(
    std::chrono::milliseconds server_default) {
  CallDeadline deadline;
  deadline.when = std::chrono::system_clock::time_point::max();
  if (server_default.count() > 0) {
    deadline.when = std::chrono::system_clock::now() + server_default;
    deadline.server_default = server_default;
  }
  return deadline;
}

Status CallDeadline::ExceededStatus(std::string_view doing) const {
  std::string message = "deadline passed while " + std::string(doing);
  if (ServerEnforced()) {
    message += " (the server's default of " +
               std::to_string(server_default.count()) +
               " ms; the call set no deadline)";
  }
  return Status::DeadlineExceeded(message);
}

}  // namespace locator
