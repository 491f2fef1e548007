// What the application needs to know of a gRPC call, read from its
// context: the authorization it presents, its deadline, and the control a
// LocateBatch runs under.
//
// Thread-safety: free functions; each reads the one call it is given.

#ifndef LOCATOR_SERVER_GRPC_CALL_CONTEXT_H_
#define LOCATOR_SERVER_GRPC_CALL_CONTEXT_H_

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <optional>
#include <string_view>

#include "server/app/batch_locator.h"
#include "server/serving/call_deadline.h"

namespace locator {

// The "authorization" metadata of the call of `context` (nullopt when it
// has none).
std::optional<std::string_view> AuthorizationOf(
    const grpc::ServerContextBase& context);

// The deadline of the call of `context`, with `server_default` (zero: none)
// standing in for a deadline the client did not set.
CallDeadline DeadlineOf(const grpc::CallbackServerContext& context,
                        std::chrono::milliseconds server_default);

// The control of the unary call of `context`: its deadline (see
// DeadlineOf) and cancellation, finishing `reactor`.
BatchLocator::CallControl UnaryCallControl(
    grpc::CallbackServerContext* context, grpc::ServerUnaryReactor* reactor,
    std::chrono::milliseconds server_default);

}  // namespace locator

#endif  // LOCATOR_SERVER_GRPC_CALL_CONTEXT_H_
