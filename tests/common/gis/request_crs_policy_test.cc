// The request CRS policy: a CRS that names a device, a FIFO, /proc or a
// file outside PROJ's data directories is refused, naming the file, in
// every form, without PROJ opening it; grids in PROJ's data directories and
// the grids the operator's dataset CRS names still work; verdicts are made
// once.

#include "common/gis/request_crs_policy.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "common/gis/crs_info.h"
#include "common/gis/crs_transformer.h"
#include "common/gis/crs_verdicts.h"
#include "tests/common/gis/hostile_crs.h"
#include "tests/core/scratch_dir.h"

namespace locator::gis {
namespace {

using ::testing::HasSubstr;

// DHDN on the Bessel ellipsoid, shifted to ETRS89 by PROJ's German grid.
std::string BesselWithGrid(const std::string& grid) {
  return "+proj=longlat +ellps=bessel +nadgrids=" + grid + " +type=crs";
}

// Lon/lat points in Germany, where BETA2007.gsb has data, and within UTM
// zone 32N's area of use (6°E to 12°E).
std::vector<Point2> GermanPoints() {
  return {{7.5, 50.1}, {10.0, 51.0}, {11.6, 48.1}, {11.0, 53.5}};
}

TEST(RequestCrsPolicyTest, HostileCrssAreRefusedNamingTheFile) {
  test::ScratchDir dir;
  const testing::FifoWatch fifo(dir.path() + "/grid.fifo");
  // A real grid: were PROJ allowed to open it, the CRS would be made.
  const std::string outside = testing::CopyOfBeta2007Grid(dir.path());
  for (const testing::HostileCrs& row :
       testing::HostileCrss(fifo.path(), outside, kMaxRequestCrsBytes + 1)) {
    Status status = CreateRequestCrs(row.crs).status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument)
        << row.what << ": " << status.ToString();
    EXPECT_THAT(status.message(), HasSubstr(row.file)) << row.what;
    status = CheckRequestCrs(row.crs);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << row.what;
    status = CrsTransformer::Create(row.crs, "EPSG:32633").status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << row.what;
    CrsTransformer* cached = nullptr;
    status = CrsTransformer::ForThread(row.crs, "EPSG:32633", &cached);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << row.what;
  }
  EXPECT_FALSE(fifo.opened()) << "PROJ opened " << fifo.path();
}

// An unknown CRS gets PROJ's own words for it, whatever failed before on
// the thread (PROJ leaves an earlier failure's code in the context).
TEST(RequestCrsPolicyTest, AnUnknownCrsIsRefusedInWordsOfItsOwn) {
  std::string fresh;
  std::thread([&] {
    fresh = CreateRequestCrs("/etc/passwd").status().message();
  }).join();
  EXPECT_THAT(fresh, HasSubstr("unknown CRS '/etc/passwd': "));
  for (const std::string before :
       {"+proj=nonsense", "GEOGCRS[", "EPSG:999999", "+proj=longlat +a=-1"}) {
    EXPECT_FALSE(CreateRequestCrs(before).ok()) << before;
    EXPECT_EQ(CreateRequestCrs("/etc/passwd").status().message(), fresh)
        << "after " << before;
  }
  // PROJ's words stay on one line, whatever the CRS's text holds.
  for (const std::string crs :
       {std::string("GEOGCRS[\"a\nb\x01\",DATUM[\n"),
        std::string("+proj=\x02\n"),
        "PROJCRS[\"" + std::string(5000, '\n') + "\""}) {
    const std::string message = CreateRequestCrs(crs).status().message();
    EXPECT_FALSE(message.empty());
    EXPECT_EQ(message.find_first_of(std::string("\x01\x02\n\r", 4)),
              std::string::npos)
        << message;
  }
}

TEST(RequestCrsPolicyTest, TheLengthLimitIsNamed) {
  const std::string at_limit(kMaxRequestCrsBytes, ' ');
  EXPECT_TRUE(CheckRequestCrsLength(at_limit).ok());
  const Status over = CheckRequestCrsLength(at_limit + " ");
  EXPECT_EQ(over.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(over.message(), HasSubstr("a CRS of 16385 bytes ('     "));
  EXPECT_THAT(over.message(), HasSubstr("at most 16384 bytes are accepted"));
}

TEST(RequestCrsPolicyTest, GridsInProjsDataDirectoriesAreUsed) {
  const std::string request = BesselWithGrid("BETA2007.gsb");
  ASSERT_TRUE(CreateRequestCrs(request).ok());
  const StatusOr<std::unique_ptr<CrsTransformer>> with_grid =
      CrsTransformer::Create(request, "EPSG:25832");
  ASSERT_TRUE(with_grid.ok());
  const StatusOr<std::unique_ptr<CrsTransformer>> without_grid =
      CrsTransformer::Create("+proj=longlat +ellps=bessel", "EPSG:25832");
  ASSERT_TRUE(without_grid.ok());
  std::vector<Point2> shifted = GermanPoints(), unshifted = GermanPoints();
  ASSERT_TRUE((*with_grid)->ToDataset(shifted).ok());
  ASSERT_TRUE((*without_grid)->ToDataset(unshifted).ok());
  // PROJ itself, in its default context, without the guard.
  PjPtr plain(
      proj_create_crs_to_crs(nullptr, request.c_str(), "EPSG:25832", nullptr));
  ASSERT_NE(plain, nullptr);
  PjPtr expected(proj_normalize_for_visualization(nullptr, plain.get()));
  ASSERT_NE(expected, nullptr);
  for (size_t i = 0; i < shifted.size(); ++i) {
    const PJ_COORD want =
        proj_trans(expected.get(), PJ_FWD,
                   proj_coord(GermanPoints()[i].x, GermanPoints()[i].y, 0, 0));
    EXPECT_NEAR(shifted[i].x, want.xy.x, 1e-6) << i;
    EXPECT_NEAR(shifted[i].y, want.xy.y, 1e-6) << i;
    // The grid made a difference of metres (DHDN is ~100 m off ETRS89).
    EXPECT_GT(std::hypot(shifted[i].x - unshifted[i].x,
                         shifted[i].y - unshifted[i].y),
              1.0)
        << i;
  }
}

// The dataset CRS is the operator's: a grid it names outside PROJ's data
// directories is used for requests, though a request could not name it.
TEST(RequestCrsPolicyTest, GridsTheDatasetCrsNamesAreUsed) {
  test::ScratchDir dir;
  const std::string copy = testing::CopyOfBeta2007Grid(dir.path());
  const StatusOr<std::unique_ptr<CrsTransformer>> to_copy =
      CrsTransformer::Create("EPSG:4258", BesselWithGrid(copy));
  ASSERT_TRUE(to_copy.ok()) << to_copy.status().ToString();
  const StatusOr<std::unique_ptr<CrsTransformer>> to_original =
      CrsTransformer::Create("EPSG:4258", BesselWithGrid("BETA2007.gsb"));
  ASSERT_TRUE(to_original.ok());
  std::vector<Point2> through_copy = GermanPoints();
  std::vector<Point2> through_original = GermanPoints();
  ASSERT_TRUE((*to_copy)->ToDataset(through_copy).ok());
  ASSERT_TRUE((*to_original)->ToDataset(through_original).ok());
  for (size_t i = 0; i < through_copy.size(); ++i) {
    EXPECT_EQ(through_copy[i].x, through_original[i].x) << i;
    EXPECT_EQ(through_copy[i].y, through_original[i].y) << i;
    EXPECT_NE(through_copy[i].x, GermanPoints()[i].x) << i;
  }
}

// The operator's own CRSs read any regular file, but no device or FIFO.
TEST(RequestCrsPolicyTest, OperatorCrssNeverOpenADeviceOrAFifo) {
  test::ScratchDir dir;
  const testing::FifoWatch fifo(dir.path() + "/init.fifo");
  for (const std::string& init : {fifo.path(), std::string("/dev/ptmx")}) {
    const Status status = DescribeCrs("+init=" + init + ":crs").status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << init;
    EXPECT_THAT(status.message(),
                HasSubstr("'" + init + "' (not a regular file)"));
  }
  EXPECT_FALSE(fifo.opened());
}

TEST(CrsVerdictsTest, AFailureIsMadeOnceWhateverTheThreads) {
  CrsVerdicts verdicts;
  std::atomic<int> makes{0};
  const auto fail = [&] {
    ++makes;
    return Status::InvalidArgument("hostile");
  };
  std::vector<std::thread> threads;
  std::atomic<int> refused{0};
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 125; ++i) {
        if (verdicts.Decide("+nadgrids=/dev/ptmx", fail).message() ==
            "hostile") {
          ++refused;
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(makes.load(), 1);
  EXPECT_EQ(refused.load(), 1000);
}

TEST(CrsVerdictsTest, AGoodKeyIsMadeForEveryCaller) {
  CrsVerdicts verdicts;
  int makes = 0;
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(verdicts
                    .Decide("EPSG:4326",
                            [&] {
                              ++makes;
                              return Status::OK();
                            })
                    .ok());
  }
  EXPECT_EQ(makes, 3);
}

TEST(CrsVerdictsTest, HoldsAtMostItsCapacity) {
  CrsVerdicts verdicts;
  int makes = 0;
  const auto fail = [&] {
    ++makes;
    return Status::InvalidArgument("no");
  };
  for (size_t key = 0; key < CrsVerdicts::kCapacity; ++key) {
    (void)verdicts.Decide(std::to_string(key), fail);
  }
  (void)verdicts.Decide("0", fail);  // still known
  EXPECT_EQ(makes, static_cast<int>(CrsVerdicts::kCapacity));
  (void)verdicts.Decide("one more", fail);  // forgets the others
  (void)verdicts.Decide("0", fail);
  EXPECT_EQ(makes, static_cast<int>(CrsVerdicts::kCapacity) + 2);
}

}  // namespace
}  // namespace locator::gis
