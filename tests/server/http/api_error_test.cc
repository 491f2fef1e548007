#include "server/http/api_error.h"

#include <gtest/gtest.h>

#include <string>

#include "server/grpc/status_mapping.h"
#include "tests/server/http/json_value.h"

namespace locator {
namespace {

using test::JsonValue;
using test::ParseJson;

TEST(ApiErrorTest, IsTheStatusAsJsonWithItsHttpStatus) {
  const HttpResponse response =
      ApiError(grpc::Status(grpc::StatusCode::NOT_FOUND, "no 'x'"));
  EXPECT_EQ(response.status, 404u);
  EXPECT_EQ(response.content_type, "application/json");
  EXPECT_EQ(response.body,
            R"({"code":5,"status":"NOT_FOUND","message":"no 'x'"})");
  EXPECT_EQ(
      ApiError(grpc::Status(grpc::StatusCode::UNIMPLEMENTED, "m"), 405).status,
      405u);
}

// A status made anywhere (not only by ToGrpcStatus) is cut as ToGrpcStatus
// cuts a gRPC one, so that no echo of a request makes a reply of its size.
TEST(ApiErrorTest, CutsTheMessageAsToGrpcStatusDoes) {
  const std::string huge = "quoted '" + std::string(size_t{1} << 20, 'q');
  const HttpResponse response =
      ApiError(grpc::Status(grpc::StatusCode::INVALID_ARGUMENT, huge));
  JsonValue error;
  ASSERT_TRUE(ParseJson(response.body, &error).ok());
  const std::string& message = error["message"].string();
  EXPECT_EQ(message.size(), kMaxStatusMessageBytes);
  EXPECT_EQ(message,
            ToGrpcStatus(Status::InvalidArgument(huge)).error_message());
  EXPECT_EQ(message.substr(message.size() - 3), "...");
}

}  // namespace
}  // namespace locator
