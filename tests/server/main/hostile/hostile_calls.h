// The hostile-input test's calls: one request to a live locatord over gRPC
// (with a deadline on every call) or over its HTTP/JSON API (the test HTTP
// client's timeout), and how it ended as an Outcome.
//
// Over HTTP the request's dataset goes into the path (percent-encoded) and
// the body is the request in protobuf's JSON mapping. An HTTP reply other
// than 200 must be an ApiError whose HTTP status is its code's (or one more
// precise: 405, 413, 414, 415, 431), as JSON; anything else (or a dropped
// connection) is a transport problem, unless the expectation accepts that HTTP
// status.
//
// Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_CALLS_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_CALLS_H_

#include <google/protobuf/message.h>

#include <string>
#include <string_view>
#include <vector>

#include "locator/v1/locator.grpc.pb.h"
#include "tests/server/main/hostile/hostile_expect.h"
#include "tests/server/main/hostile/hostile_server.h"
#include "tests/server/http/http_test_client.h"

namespace locator::test {

// The unary RPCs; `response` is filled when the outcome is OK.
Outcome CallLocate(HostileServer& server, Transport transport,
                   const v1::LocateRequest& request,
                   v1::LocateResponse* response);
Outcome CallLocateBatch(HostileServer& server, Transport transport,
                        const v1::LocateBatchRequest& request,
                        v1::LocateBatchResponse* response);
Outcome CallProfile(HostileServer& server, Transport transport,
                    const v1::ProfileRequest& request,
                    v1::ProfileResponse* response);
// A Grid as one message, the header and every row in order (the HTTP
// form); over gRPC, a row that comes twice or not at all, or a header that
// is not first, is a transport problem.
Outcome CallGrid(HostileServer& server, Transport transport,
                 const v1::GridRequest& request, v1::GridResponse* whole);
// One LocateStream: every request written (from a second thread: the
// server stops reading while answers wait unread), every answer read.
Outcome CallStream(HostileServer& server,
                   const std::vector<v1::LocateRequest>& requests,
                   std::vector<v1::LocateResponse>* answers);

// Sends `method` `target` with `body` and `headers` to the HTTP server and
// reads the reply as an API call's; on 200, parses the body into
// `response` unless it is null. `reply`, unless null, gets the reply.
Outcome CallHttp(int port, std::string_view method, std::string_view target,
                 std::string_view body, const HttpHeaders& headers,
                 google::protobuf::Message* response,
                 HttpReply* reply = nullptr);

// `text` percent-encoded for a path segment.
std::string PercentEncode(std::string_view text);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_CALLS_H_
