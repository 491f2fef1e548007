#include "common/status_mapping.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "common/input_text.h"

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
      {Status::Cancelled("gone"), grpc::StatusCode::CANCELLED},
      {Status::DeadlineExceeded("late"), grpc::StatusCode::DEADLINE_EXCEEDED},
      {Status::Unauthenticated("who"), grpc::StatusCode::UNAUTHENTICATED},
      {Status::PermissionDenied("no"), grpc::StatusCode::PERMISSION_DENIED},
      {Status::Unimplemented("how"), grpc::StatusCode::UNIMPLEMENTED},
  };
  for (const auto& [status, code] : cases) {
    const grpc::Status mapped = ToGrpcStatus(status);
    EXPECT_EQ(mapped.error_code(), code) << status.ToString();
    EXPECT_EQ(mapped.error_message(), status.message());
  }
}

// gRPC sends the message in a header: a longer one than the client accepts
// would reach it as an unrelated error.
TEST(StatusMappingTest, ALongMessageIsCutToFitAHeader) {
  const std::string huge =
      "the request names CRS '" + std::string(10 << 20, 'x');
  for (const grpc::Status& mapped :
       {ToGrpcStatus(Status::InvalidArgument(huge)),
        ToGrpcStatus(Status::PermissionDenied(huge))}) {
    EXPECT_EQ(mapped.error_message().size(), kMaxStatusMessageBytes);
    EXPECT_TRUE(
        mapped.error_message().starts_with("the request names CRS 'xxx"));
    EXPECT_TRUE(mapped.error_message().ends_with("xx..."));
  }
  const std::string longest(kMaxStatusMessageBytes, 'y');
  EXPECT_EQ(ToGrpcStatus(Status::NotFound(longest)).error_message(), longest);
}

}  // namespace
}  // namespace locator
