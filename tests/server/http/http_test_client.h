// Blocking HTTP/1.1 requests to 127.0.0.1 for the status server's tests
// (Boost.Beast), one connection per call unless a connection is kept.
//
// Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_HTTP_HTTP_TEST_CLIENT_H_
#define LOCATOR_TESTS_SERVER_HTTP_HTTP_TEST_CLIENT_H_

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "locator/status.h"

namespace locator::test {

struct HttpReply {
  unsigned status = 0;
  std::map<std::string, std::string> headers;  // names in lower case
  std::string body;
};

// Header fields to send, in order.
using HttpHeaders = std::vector<std::pair<std::string, std::string>>;

// Sends `method` `target` with `headers` and `body` (with its
// Content-Length; none when empty and the method is not POST) to
// 127.0.0.1:port and reads the reply. IOError if the connection fails or
// closes before a complete reply.
Status SendHttp(int port, std::string_view method, std::string_view target,
                HttpReply* reply, std::string_view body = {},
                const HttpHeaders& headers = {});

// GET, the usual case.
inline Status HttpGet(int port, std::string_view target, HttpReply* reply) {
  return SendHttp(port, "GET", target, reply);
}

// Writes `raw` bytes to a fresh connection from the loopback address `from`
// and returns everything the server sends back until it closes the
// connection (or 120 s pass).
Status RawExchange(int port, std::string_view raw, std::string* received,
                   std::string_view from = "127.0.0.1");

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_HTTP_TEST_CLIENT_H_
