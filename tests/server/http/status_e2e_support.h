// LocatordWithHttp: the real locatord started with --http-listen on ports
// the OS picks, for the status server's end-to-end tests.
//
// locatord prints "locatord listening on HOST:PORT" (gRPC) and then
// "locatord http listening on HOST:PORT"; ServerProcess::WaitForListening()
// reads up to the next line of that shape, so Start() calls it twice and
// keeps both addresses. Serving is awaited over HTTP (/api/stats answers
// 200 once an engine serves), so the test makes every gRPC call itself and
// can count them exactly.
//
// Owns the ServerProcess. Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_HTTP_STATUS_E2E_SUPPORT_H_
#define LOCATOR_TESTS_SERVER_HTTP_STATUS_E2E_SUPPORT_H_

#include <memory>
#include <string>
#include <vector>

#include "locator/status.h"
#include "locator/v1/locator.grpc.pb.h"
#include "tests/server/http/json_value.h"
#include "tests/testing/server_process.h"

namespace locator::test {

class LocatordWithHttp {
 public:
  // Starts locatord serving `dataset` with `flags` added, and waits until it
  // serves; `data_token` is the token the flags make it want ("": none).
  static Status Start(const std::string& dataset,
                      const std::vector<std::string>& flags,
                      std::unique_ptr<LocatordWithHttp>* server,
                      const std::string& data_token = "");

  // Waits until dataset `dataset` ("": the default) serves: /api/stats
  // answers 200 for it (asked with the data token). Unavailable, with
  // stderr, if the server exits or 60 s pass first.
  Status WaitUntilServes(const std::string& dataset);

  ServerProcess& process() { return *process_; }
  int http_port() const { return http_port_; }
  const std::string& grpc_target() const { return grpc_target_; }
  std::unique_ptr<v1::Locator::Stub> NewStub() const;

 private:
  LocatordWithHttp() = default;

  std::unique_ptr<ServerProcess> process_;
  std::string grpc_target_;
  int http_port_ = 0;
  std::string data_token_;
};

// GETs `target` and parses its body as JSON; a failure is reported as a
// test failure and yields null.
JsonValue GetJson(int port, const std::string& target);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_STATUS_E2E_SUPPORT_H_
