// ApiError: how locatord's HTTP server answers a failed call, whatever the
// endpoint: the gRPC status the same call would have ended with over gRPC,
// as the HTTP status HttpStatusFor() maps it to (or `http_status`, where
// HTTP has a more precise one: 413 for a body over the limit, 405 for a
// method a path does not take) and the JSON body
//
//   {"code": <gRPC code number>, "status": "<gRPC code name>",
//    "message": "<the gRPC message>"}
//
// The message is cut to kMaxStatusMessageBytes, as ToGrpcStatus cuts a gRPC
// one, whichever way the status was made.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_SERVER_HTTP_API_ERROR_H_
#define LOCATOR_SERVER_HTTP_API_ERROR_H_

#include <grpcpp/support/status.h>

#include <string>

#include "server/http/http_server.h"

namespace locator {

inline constexpr char kJsonContentType[] = "application/json";

// The answer to a call that failed with `status` (not OK); `http_status`
// 0: HttpStatusFor(status.error_code()).
HttpResponse ApiError(const grpc::Status& status, unsigned http_status = 0);

// Seconds a refused client is told to wait (Retry-After) before it retries.
inline constexpr int kRetryAfterSeconds = 1;

// The answer to a call refused because the server is busy (a limit on
// connections or queued calls): UNAVAILABLE with `message`, 503, and
// Retry-After.
HttpResponse BusyError(const std::string& message);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_API_ERROR_H_
