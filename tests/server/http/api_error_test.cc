#include "server/http/api_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/input_text.h"
#include "common/status_mapping.h"
#include "tests/server/http/json_value.h"

namespace locator {
namespace {

using test::JsonValue;
using test::ParseJson;

TEST(ApiErrorTest, IsTheStatusAsJsonWithItsHttpStatus) {
  const HttpResponse response = ApiError(Status::NotFound("no 'x'"));
  EXPECT_EQ(response.status, 404u);
  EXPECT_EQ(response.content_type, "application/json");
  EXPECT_EQ(response.body,
            R"({"code":5,"status":"NOT_FOUND","message":"no 'x'"})");
  EXPECT_EQ(ApiError(Status::Unimplemented("m"), 405).status, 405u);
  // A file that could not be read is the server's failure, as over gRPC.
  EXPECT_EQ(ApiError(Status::IOError("m")).body,
            R"({"code":13,"status":"INTERNAL","message":"m"})");
}

// A status made anywhere (not only by ToGrpcStatus) is cut as ToGrpcStatus
// cuts a gRPC one, so that no echo of a request makes a reply of its size.
TEST(ApiErrorTest, CutsTheMessageAsToGrpcStatusDoes) {
  const std::string huge = "quoted '" + std::string(size_t{1} << 20, 'q');
  const HttpResponse response = ApiError(Status::InvalidArgument(huge));
  JsonValue error;
  ASSERT_TRUE(ParseJson(response.body, &error).ok());
  const std::string& message = error["message"].string();
  EXPECT_EQ(message.size(), kMaxStatusMessageBytes);
  EXPECT_EQ(message,
            ToGrpcStatus(Status::InvalidArgument(huge)).error_message());
  EXPECT_EQ(message.substr(message.size() - 3), "...");
}

TEST(ApiErrorTest, EveryCanonicalCodeHasTheGatewaysHttpStatus) {
  using Code = grpc::StatusCode;
  const std::vector<std::pair<Code, unsigned>> cases = {
      {Code::OK, 200},
      {Code::CANCELLED, 499},
      {Code::UNKNOWN, 500},
      {Code::INVALID_ARGUMENT, 400},
      {Code::DEADLINE_EXCEEDED, 504},
      {Code::NOT_FOUND, 404},
      {Code::ALREADY_EXISTS, 409},
      {Code::PERMISSION_DENIED, 403},
      {Code::RESOURCE_EXHAUSTED, 429},
      {Code::FAILED_PRECONDITION, 400},
      {Code::ABORTED, 409},
      {Code::OUT_OF_RANGE, 400},
      {Code::UNIMPLEMENTED, 501},
      {Code::INTERNAL, 500},
      {Code::UNAVAILABLE, 503},
      {Code::DATA_LOSS, 500},
      {Code::UNAUTHENTICATED, 401},
  };
  for (const auto& [code, http] : cases) {
    EXPECT_EQ(HttpStatusForCanonicalCode(static_cast<int>(code)), http)
        << static_cast<int>(code);
  }
}

TEST(ApiErrorTest, ANumberOutsideTheCanonicalCodesIsA500) {
  EXPECT_EQ(HttpStatusForCanonicalCode(-1), 500u);
  EXPECT_EQ(HttpStatusForCanonicalCode(17), 500u);
}

// The HTTP API names the canonical code a gRPC client of the same call gets.
TEST(ApiErrorTest, GrpcAndHttpShowTheSameCanonicalCode) {
  const std::vector<Status> every_code = {
      Status::OK(),
      Status::InvalidArgument("m"),
      Status::NotFound("m"),
      Status::FailedPrecondition("m"),
      Status::ResourceExhausted("m"),
      Status::Unavailable("m"),
      Status::Internal("m"),
      Status::IOError("m"),
      Status::Cancelled("m"),
      Status::DeadlineExceeded("m"),
      Status::Unauthenticated("m"),
      Status::PermissionDenied("m"),
      Status::Unimplemented("m"),
  };
  ASSERT_EQ(every_code.size(),
            static_cast<size_t>(Status::Code::kUnimplemented) + 1);
  for (const Status& status : every_code) {
    EXPECT_EQ(static_cast<int>(ToGrpcStatus(status).error_code()),
              CanonicalCode(status.code()))
        << status.ToString();
  }
}

// Open Topo Data's clients read its shape and its statuses: every fault of
// the caller's is 400 INVALID_REQUEST, an unknown dataset included.
TEST(ApiErrorTest, OpenTopoDataErrorsHaveItsShapeAndStatuses) {
  const struct {
    Status status;
    unsigned http;
    std::string name;
  } cases[] = {
      {Status::InvalidArgument("bad"), 400, "INVALID_REQUEST"},
      {Status::NotFound("unknown dataset 'lava'"), 400, "INVALID_REQUEST"},
      {Status::ResourceExhausted("too many"), 400, "INVALID_REQUEST"},
      {Status::FailedPrecondition("no"), 400, "INVALID_REQUEST"},
      {Status::Unauthenticated("token"), 401, "REQUEST_DENIED"},
      {Status::PermissionDenied("token"), 403, "REQUEST_DENIED"},
      {Status::Unavailable("busy"), 503, "SERVER_ERROR"},
      {Status::DeadlineExceeded("late"), 504, "SERVER_ERROR"},
      {Status::Internal("bug"), 500, "SERVER_ERROR"},
  };
  for (const auto& c : cases) {
    const HttpResponse answer = OpenTopoDataError(c.status);
    EXPECT_EQ(answer.status, c.http) << c.status.ToString();
    EXPECT_EQ(answer.content_type, "application/json");
    JsonValue json;
    ASSERT_TRUE(test::ParseJson(answer.body, &json).ok()) << answer.body;
    EXPECT_EQ(json.object().size(), 2u) << answer.body;
    EXPECT_EQ(json["status"].string(), c.name) << answer.body;
    EXPECT_EQ(json["error"].string(), c.status.message()) << answer.body;
    const bool retry_after =
        !answer.headers.empty() && answer.headers[0].first == "Retry-After";
    EXPECT_EQ(retry_after, c.http == 503) << c.status.ToString();
  }
  // Cut as every status message is.
  const HttpResponse long_answer =
      OpenTopoDataError(Status::InvalidArgument(std::string(100000, 'x')));
  EXPECT_LT(long_answer.body.size(), kMaxStatusMessageBytes + 100);
}

}  // namespace
}  // namespace locator
