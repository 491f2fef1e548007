// Helpers of the HTTP/JSON API's end-to-end tests: messages to and from
// their JSON mapping, field-by-field comparison, POSTs and API errors.
//
// Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_HTTP_JSON_API_SUPPORT_H_
#define LOCATOR_TESTS_SERVER_HTTP_JSON_API_SUPPORT_H_

#include <google/protobuf/message.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/server/http/http_test_client.h"

namespace locator::test {

// `message` as its JSON mapping, as a client would write it.
std::string ToJson(const google::protobuf::Message& message);

// Parses a JSON answer into `message`; a failure is a test failure.
template <typename Message>
Message FromJson(const std::string& json) {
  Message message;
  const auto status =
      google::protobuf::util::JsonStringToMessage(json, &message);
  EXPECT_TRUE(status.ok()) << status.ToString() << "\n" << json.substr(0, 300);
  return message;
}

// Whether `a` and `b` are equal field by field (NaN equal to NaN: batch
// values outside the hull, nodata cells).
::testing::AssertionResult SameProto(const google::protobuf::Message& a,
                                     const google::protobuf::Message& b);

// POSTs `body` to `target` as Content-Type: application/json, with
// `headers`; a failed exchange is a test failure.
HttpReply Post(int port, const std::string& target, const std::string& body,
               const HttpHeaders& headers = {});

// Checks that `reply` is the API error `code` with HTTP status `http` and
// a message containing `message`.
void ExpectError(const HttpReply& reply, unsigned http, grpc::StatusCode code,
                 const std::string& message);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_JSON_API_SUPPORT_H_
