#include "tests/server/http/hill_server_test.h"

#include <string>

#include "tests/common/gis/gis_fixtures.h"

namespace locator::test {

ScratchDir* HillServerTest::dir_ = nullptr;
std::unique_ptr<LocatordWithHttp> HillServerTest::server_;

void HillServerTest::SetUpTestSuite() {
  dir_ = new ScratchDir();
  const std::string gpkg =
      gis::testing::UtmHillGeoPackage(kHillSide, dir_->path());
  const Status started = LocatordWithHttp::Start(
      "terrain=" + gpkg, {"--dataset", "plain=uniform:3000:5"}, &server_);
  ASSERT_TRUE(started.ok()) << started.ToString();
  ASSERT_TRUE(server_->WaitUntilServes("plain").ok());
}

void HillServerTest::TearDownTestSuite() {
  server_.reset();
  delete dir_;
  dir_ = nullptr;
}

}  // namespace locator::test
