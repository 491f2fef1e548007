#include "tests/server/http/json_api_support.h"

#include <gmock/gmock.h>
#include <google/protobuf/util/field_comparator.h>
#include <google/protobuf/util/message_differencer.h>

#include "tests/server/http/json_value.h"

namespace locator::test {

std::string ToJson(const google::protobuf::Message& message) {
  std::string json;
  EXPECT_TRUE(google::protobuf::util::MessageToJsonString(message, &json).ok());
  return json;
}

::testing::AssertionResult SameProto(const google::protobuf::Message& a,
                                     const google::protobuf::Message& b) {
  google::protobuf::util::DefaultFieldComparator comparator;
  comparator.set_treat_nan_as_equal(true);
  google::protobuf::util::MessageDifferencer differencer;
  differencer.set_field_comparator(&comparator);
  std::string differences;
  differencer.ReportDifferencesToString(&differences);
  if (differencer.Compare(a, b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << differences.substr(0, 2000);
}

HttpReply Post(int port, const std::string& target, const std::string& body,
               const HttpHeaders& headers) {
  HttpHeaders sent_headers = headers;
  sent_headers.emplace_back("Content-Type", "application/json");
  HttpReply reply;
  const Status sent =
      SendHttp(port, "POST", target, &reply, body, sent_headers);
  EXPECT_TRUE(sent.ok()) << sent.ToString();
  return reply;
}

void ExpectError(const HttpReply& reply, unsigned http, grpc::StatusCode code,
                 const std::string& message) {
  const std::string shown = reply.body.substr(0, 300);
  EXPECT_EQ(reply.status, http) << shown;
  EXPECT_EQ(reply.headers.at("content-type"), "application/json");
  JsonValue error;
  ASSERT_TRUE(ParseJson(reply.body, &error).ok()) << shown;
  if (reply.status == 200) return;  // not an error: nothing more to check
  EXPECT_EQ(error["code"].number(), static_cast<int>(code)) << shown;
  EXPECT_EQ(error["status"].string().empty(), false);
  EXPECT_THAT(error["message"].string(), ::testing::HasSubstr(message))
      << shown;
}

}  // namespace locator::test
