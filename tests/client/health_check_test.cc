#include "client/health_check.h"

#include <gtest/gtest.h>

#include <string>

namespace locator {
namespace {

using namespace std::string_literals;

TEST(HealthCheckTest, EncodesTheServiceName) {
  EXPECT_EQ(EncodeHealthCheckRequest(""), "");
  EXPECT_EQ(EncodeHealthCheckRequest("locator.v1.Locator"),
            "\x0a\x12locator.v1.Locator"s);
}

// The status `wire` decodes to; fails the test if it does not decode.
HealthStatus Decoded(const std::string& wire) {
  HealthStatus status = HealthStatus::kNotServing;
  EXPECT_TRUE(DecodeHealthCheckResponse(wire, &status));
  return status;
}

TEST(HealthCheckTest, DecodesTheStatus) {
  EXPECT_EQ(Decoded("\x08\x01"s), HealthStatus::kServing);
  EXPECT_EQ(Decoded("\x08\x02"s), HealthStatus::kNotServing);
  // An empty message is the default status.
  EXPECT_EQ(Decoded(""), HealthStatus::kUnknown);
}

TEST(HealthCheckTest, SkipsUnknownFieldsAndValues) {
  // Field 2 (a string) before the status.
  EXPECT_EQ(Decoded("\x12\x02hi\x08\x01"s), HealthStatus::kServing);
  // A status newer than this client.
  EXPECT_EQ(Decoded("\x08\x09"s), HealthStatus::kUnknown);
}

TEST(HealthCheckTest, RejectsMalformedMessages) {
  HealthStatus status = HealthStatus::kUnknown;
  EXPECT_FALSE(DecodeHealthCheckResponse("\x08"s, &status));
  EXPECT_FALSE(DecodeHealthCheckResponse("\x12\x05hi"s, &status));
}

TEST(HealthCheckTest, NamesAsTheProtoDoes) {
  EXPECT_EQ(HealthStatusName(HealthStatus::kServing), "SERVING");
  EXPECT_EQ(HealthStatusName(HealthStatus::kNotServing), "NOT_SERVING");
  EXPECT_EQ(HealthStatusName(HealthStatus::kServiceUnknown), "SERVICE_UNKNOWN");
}

}  // namespace
}  // namespace locator
