#include "locator/status_or.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "common/status_macros.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

StatusOr<int> Half(int n) {
  if (n % 2 != 0) return Status::InvalidArgument("odd: " + std::to_string(n));
  return n / 2;
}

StatusOr<int> Quarter(int n) {
  ASSIGN_OR_RETURN(const int half, Half(n));
  ASSIGN_OR_RETURN(int quarter, Half(half));
  return quarter;
}

int evaluations = 0;
Status CountedCheck(bool ok) {
  ++evaluations;
  return ok ? Status::OK() : Status::NotFound("checked");
}

Status CheckTwice(bool first, bool second) {
  RETURN_IF_ERROR(CountedCheck(first));
  RETURN_IF_ERROR(CountedCheck(second));
  return Status::OK();
}

TEST(StatusOrTest, HoldsAValueOrTheFailure) {
  StatusOr<int> value = Half(8);
  ASSERT_TRUE(value.ok());
  EXPECT_TRUE(value.status().ok());
  EXPECT_EQ(*value, 4);

  StatusOr<int> failure = Half(7);
  EXPECT_FALSE(failure.ok());
  EXPECT_EQ(failure.status().code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(failure.status().message(), "odd: 7");
}

TEST(StatusOrTest, AnOkStatusWithoutAValueIsAnInternalError) {
  StatusOr<int> broken(Status::OK());
  EXPECT_FALSE(broken.ok());
  EXPECT_EQ(broken.status().code(), Status::Code::kInternal);
}

TEST(StatusOrTest, MovesOnlyValuesAndConvertsThem) {
  StatusOr<std::unique_ptr<const int>> owned = std::make_unique<int>(5);
  ASSERT_TRUE(owned.ok());
  std::unique_ptr<const int> taken = std::move(owned).value();
  EXPECT_EQ(*taken, 5);
}

TEST(StatusMacrosTest, AssignOrReturnStopsAtTheFirstFailure) {
  EXPECT_EQ(*Quarter(12), 3);
  EXPECT_THAT(Quarter(7).status().message(), HasSubstr("odd: 7"));
  // 6 halves to 3, which is odd: the second step fails.
  EXPECT_THAT(Quarter(6).status().message(), HasSubstr("odd: 3"));
}

TEST(StatusMacrosTest, ReturnIfErrorEvaluatesOnceAndStops) {
  evaluations = 0;
  EXPECT_EQ(CheckTwice(false, true).code(), Status::Code::kNotFound);
  EXPECT_EQ(evaluations, 1);
  evaluations = 0;
  EXPECT_TRUE(CheckTwice(true, true).ok());
  EXPECT_EQ(evaluations, 2);
}

TEST(StatusTest, ServingCodesHaveTheirCanonicalNames) {
  EXPECT_EQ(Status::Cancelled("x").ToString(), "CANCELLED: x");
  EXPECT_EQ(StatusCodeName(Status::Code::kDeadlineExceeded),
            "DEADLINE_EXCEEDED");
  EXPECT_EQ(StatusCodeName(Status::Code::kUnauthenticated), "UNAUTHENTICATED");
  EXPECT_EQ(StatusCodeName(Status::Code::kPermissionDenied),
            "PERMISSION_DENIED");
}

}  // namespace
}  // namespace locator
