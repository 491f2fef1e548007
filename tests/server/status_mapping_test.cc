#include "server/grpc/status_mapping.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace locator {
namespace {

TEST(StatusMappingTest, OkIsOk) {
  EXPECT_TRUE(ToGrpcStatus(Status::OK()).ok());
}

TEST(StatusMappingTest, EveryCodeMapsToItsGrpcNamesakeKeepingTheMessage) {
  const std::vector<std::pair<Status, grpc::StatusCode>> cases = {
      {Status::InvalidArgument("x is NaN"), grpc::StatusCode::INVALID_ARGUMENT},
      {Status::NotFound("no file"), grpc::StatusCode::NOT_FOUND},
      {Status::FailedPrecondition("not yet"),
       grpc::StatusCode::FAILED_PRECONDITION},
      {Status::ResourceExhausted("too big"),
       grpc::StatusCode::RESOURCE_EXHAUSTED},
      {Status::Unavailable("loading"), grpc::StatusCode::UNAVAILABLE},
      {Status::Internal("bug"), grpc::StatusCode::INTERNAL},
      // Not retryable against the same server: see status_mapping.cc.
      {Status::IOError("read failed"), grpc::StatusCode::INTERNAL},
  };
  for (const auto& [status, code] : cases) {
    const grpc::Status mapped = ToGrpcStatus(status);
    EXPECT_EQ(mapped.error_code(), code) << status.ToString();
    EXPECT_EQ(mapped.error_message(), status.message());
  }
}

TEST(StatusMappingTest, EveryRefusalHasItsCodeAndKeepsTheMessage) {
  const std::vector<std::pair<Refusal, grpc::StatusCode>> cases = {
      {Refusal::kUnauthenticated, grpc::StatusCode::UNAUTHENTICATED},
      {Refusal::kPermissionDenied, grpc::StatusCode::PERMISSION_DENIED},
      {Refusal::kShuttingDown, grpc::StatusCode::UNAVAILABLE},
  };
  for (const auto& [refusal, code] : cases) {
    const grpc::Status mapped = ToGrpcStatus(refusal, "why");
    EXPECT_EQ(mapped.error_code(), code);
    EXPECT_EQ(mapped.error_message(), "why");
  }
}

// gRPC sends the message in a header: a longer one than the client accepts
// would reach it as an unrelated error.
TEST(StatusMappingTest, ALongMessageIsCutToFitAHeader) {
  const std::string huge =
      "the request names CRS '" + std::string(10 << 20, 'x');
  for (const grpc::Status& mapped :
       {ToGrpcStatus(Status::InvalidArgument(huge)),
        ToGrpcStatus(Refusal::kPermissionDenied, huge)}) {
    EXPECT_EQ(mapped.error_message().size(), kMaxStatusMessageBytes);
    EXPECT_TRUE(
        mapped.error_message().starts_with("the request names CRS 'xxx"));
    EXPECT_TRUE(mapped.error_message().ends_with("xx..."));
  }
  const std::string longest(kMaxStatusMessageBytes, 'y');
  EXPECT_EQ(ToGrpcStatus(Status::NotFound(longest)).error_message(), longest);
}

TEST(StatusMappingTest, EveryGrpcCodeHasTheGatewaysHttpStatus) {
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
    EXPECT_EQ(HttpStatusFor(code), http) << static_cast<int>(code);
  }
}

}  // namespace
}  // namespace locator
