// FromReloadRequest: ReloadRequest.spec, and the deprecated dataset field of
// clients from before it.

#include <gtest/gtest.h>

#include <string>

#include "locator/v1/locator.pb.h"
#include "server/app/proto_convert.h"

namespace locator {
namespace {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

v1::ReloadRequest Request(const std::string& spec, const std::string& legacy) {
  v1::ReloadRequest request;
  request.set_spec(spec);
  request.set_dataset(legacy);
  return request;
}

#pragma GCC diagnostic pop

std::string SpecOf(const v1::ReloadRequest& request) {
  const StatusOr<std::string> spec = FromReloadRequest(request);
  EXPECT_TRUE(spec.ok());
  return spec.ok() ? *spec : "unset";
}

TEST(ReloadRequestTest, TheSpecIsWhatToLoad) {
  EXPECT_EQ(SpecOf(Request("hill.gpkg?layer=h", "")), "hill.gpkg?layer=h");
}

TEST(ReloadRequestTest, AnOldClientsDatasetFieldIsTheSpec) {
  EXPECT_EQ(SpecOf(Request("", "old.csv")), "old.csv");
  EXPECT_EQ(SpecOf(Request("same.csv", "same.csv")), "same.csv");
}

TEST(ReloadRequestTest, NeitherReloadsTheConfiguredDataset) {
  EXPECT_EQ(SpecOf(Request("", "")), "");
}

TEST(ReloadRequestTest, TwoDifferentSpecsAreRefusedNamingBoth) {
  const Status status = FromReloadRequest(Request("a.csv", "b.csv")).status();
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << status.ToString();
  EXPECT_NE(status.message().find("'a.csv'"), std::string::npos);
  EXPECT_NE(status.message().find("'b.csv'"), std::string::npos);
}

}  // namespace
}  // namespace locator
