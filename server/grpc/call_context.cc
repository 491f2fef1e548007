#include "server/grpc/call_context.h"

#include "common/status_mapping.h"

namespace locator {

std::optional<std::string_view> AuthorizationOf(
    const grpc::ServerContextBase& context) {
  const auto& metadata = context.client_metadata();
  const auto found = metadata.find("authorization");
  if (found == metadata.end()) return std::nullopt;
  return std::string_view(found->second.data(), found->second.size());
}

CallDeadline DeadlineOf(const grpc::CallbackServerContext& context,
                        std::chrono::milliseconds server_default) {
  // gRPC reports "no deadline" as the largest time_point.
  if (context.deadline() == std::chrono::system_clock::time_point::max()) {
    return CallDeadline::ServerDefault(server_default);
  }
  return CallDeadline{.when = context.deadline()};
}

BatchLocator::CallControl UnaryCallControl(
    grpc::CallbackServerContext* context, grpc::ServerUnaryReactor* reactor,
    std::chrono::milliseconds server_default) {
  return BatchLocator::CallControl{
      .deadline = DeadlineOf(*context, server_default),
      .cancelled = [context] { return context->IsCancelled(); },
      .finish =
          [reactor](const Status& status) {
            reactor->Finish(ToGrpcStatus(status));
          }};
}

}  // namespace locator
