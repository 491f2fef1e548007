// ApiError: how locatord's HTTP server answers a failed call, whatever the
// endpoint, and the one place where a Status becomes an HTTP status (gRPC's
// is common/status_mapping.h). The answer has the HTTP status
// HttpStatusFor() maps the status's code to (or `http_status`, where HTTP
// has a more precise one: 413 for a body over the limit, 405 for a method a
// path does not take, 406 for an Accept that takes no type the route
// answers) and the JSON body
//
//   {"code": <canonical code number>, "status": "<canonical code name>",
//    "message": "<the status's message>"}
//
// with the canonical (google.rpc.Code) numbers and names a gRPC client of
// the same call sees. The message is cut to kMaxStatusMessageBytes, as a
// gRPC one is.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_HTTP_API_ERROR_H_
#define LOCATOR_SERVER_HTTP_API_ERROR_H_

#include <string>
#include <string_view>

#include "locator/status.h"
#include "server/http/http_server.h"

namespace locator {

inline constexpr char kJsonContentType[] = "application/json";

// The canonical (google.rpc.Code, gRPC's) number of `code`; IO_ERROR is
// INTERNAL (13), as over gRPC.
int CanonicalCode(Status::Code code);
// The HTTP status of a call that ended with canonical code `canonical`, as
// grpc-gateway maps them: OK 200; INVALID_ARGUMENT, FAILED_PRECONDITION and
// OUT_OF_RANGE 400; UNAUTHENTICATED 401; PERMISSION_DENIED 403; NOT_FOUND
// 404; ALREADY_EXISTS and ABORTED 409; RESOURCE_EXHAUSTED 429; CANCELLED
// 499; UNIMPLEMENTED 501; UNAVAILABLE 503; DEADLINE_EXCEEDED 504; the rest
// (and a number outside the canonical codes) 500.
unsigned HttpStatusForCanonicalCode(int canonical);
// HttpStatusForCanonicalCode(CanonicalCode(code)).
unsigned HttpStatusFor(Status::Code code);

// The answer to a call that failed with `status` (not OK); `http_status`
// 0: HttpStatusFor(status.code()).
HttpResponse ApiError(const Status& status, unsigned http_status = 0);
// The answer to a call that failed with canonical code `canonical` (a gRPC
// status code's number, as a router hands on a shard's) and `message`.
HttpResponse ApiError(int canonical, std::string_view message);

// Seconds a refused client is told to wait (Retry-After) before it retries.
inline constexpr int kRetryAfterSeconds = 1;

// The answer to a call refused because the server is busy (a limit on
// connections or queued calls): UNAVAILABLE with `message`, 503, and
// Retry-After.
HttpResponse BusyError(const std::string& message);

// The answer to a failed Open Topo Data call (Google Elevation's shape):
//
//   {"error": "<the status's message>", "status": "<STATUS>"}
//
// Open Topo Data answers every client error 400 INVALID_REQUEST, an unknown
// dataset and too many locations included, so INVALID_ARGUMENT,
// FAILED_PRECONDITION, NOT_FOUND and RESOURCE_EXHAUSTED are
// 400 INVALID_REQUEST; a refused token keeps its 401 or 403 with Google's
// REQUEST_DENIED; the rest keep HttpStatusFor()'s status with
// SERVER_ERROR, and UNAVAILABLE adds Retry-After as BusyError() does.
HttpResponse OpenTopoDataError(const Status& status);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_API_ERROR_H_
