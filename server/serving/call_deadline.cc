#include "server/serving/call_deadline.h"

#include <string>

namespace locator {

CallDeadline CallDeadline::For(const grpc::CallbackServerContext& context,
                               std::chrono::milliseconds server_default) {
  // gRPC reports "no deadline" as the largest time_point.
  if (context.deadline() == std::chrono::system_clock::time_point::max()) {
    return ServerDefault(server_default);
  }
  return CallDeadline{.when = context.deadline()};
}

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

grpc::Status CallDeadline::ExceededStatus(std::string_view doing) const {
  std::string message = "deadline passed while " + std::string(doing);
  if (ServerEnforced()) {
    message += " (the server's default of " +
               std::to_string(server_default.count()) +
               " ms; the call set no deadline)";
  }
  return grpc::Status(grpc::StatusCode::DEADLINE_EXCEEDED, message);
}

}  // namespace locator
