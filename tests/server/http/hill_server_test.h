// HillServerTest: a test suite's locatord serving the hill of
// kHillSide x kHillSide points in UTM zone 33N (a GeoPackage made by
// ogr2ogr, gis::testing::UtmHillGeoPackage) as "terrain", its default,
// beside "plain", a generated dataset without a CRS: what the tile routes'
// end-to-end tests query. Started once per suite, stopped after it.
//
// Thread-safety: the test thread only.

#ifndef LOCATOR_TESTS_SERVER_HTTP_HILL_SERVER_TEST_H_
#define LOCATOR_TESTS_SERVER_HTTP_HILL_SERVER_TEST_H_

#include <gtest/gtest.h>

#include <memory>

#include "tests/core/scratch_dir.h"
#include "tests/server/http/status_e2e_support.h"

namespace locator::test {

class HillServerTest : public ::testing::Test {
 protected:
  // 900 points, 400 m apart: ~12 km around 15°E 49.6525°N.
  static constexpr int kHillSide = 30;

  static void SetUpTestSuite();
  static void TearDownTestSuite();
  int port() const { return server_->http_port(); }

  static ScratchDir* dir_;
  static std::unique_ptr<LocatordWithHttp> server_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_HILL_SERVER_TEST_H_
