// Hostile request CRSs against the real locatord (issue 26, hole 3): a CRS
// naming a device, a FIFO made here, /proc, a regular file outside PROJ's
// data directories, an +init or +geoidgrids file, in PROJ string, WKT and
// PROJJSON form, or one past the length limit, is INVALID_ARGUMENT on every
// RPC and HTTP route that takes a CRS, as often as it is sent; PROJ never
// opens the FIFO; the server keeps answering, a legitimate CRS still works,
// and SIGTERM still stops it.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common/gis/request_crs_policy.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/common/gis/hostile_crs.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

using gis::testing::FifoWatch;
using gis::testing::HostileCrs;
using ::testing::HasSubstr;

// More than the three calls that used to take every gRPC thread.
constexpr int kRepeats = 5;
// A bound on a call that used to hang forever; no answer is timed.
constexpr auto kCallDeadline = std::chrono::seconds(60);

// A point on the hill (15°E, 49.65°N) in the hill's UTM zone 33N.
constexpr Point2 kOnTheHill{500000, 5500000};

void SetDeadline(grpc::ClientContext* context) {
  context->set_deadline(std::chrono::system_clock::now() + kCallDeadline);
}

class LocatordHostileCrsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    gpkg_ = gis::testing::UtmHillGeoPackage(15, dir_.path());
    std::filesystem::create_directory(dir_.path() + "/grids");
    outside_ = gis::testing::CopyOfBeta2007Grid(dir_.path() + "/grids");
    fifo_ = std::make_unique<FifoWatch>(dir_.path() + "/grid.fifo");
    ASSERT_TRUE(LocatordWithHttp::Start(gpkg_, {}, &server_).ok());
    stub_ = server_->NewStub();
  }

  std::vector<HostileCrs> Rows() const {
    return gis::testing::HostileCrss(fifo_->path(), outside_,
                                     gis::kMaxRequestCrsBytes + 1);
  }

  grpc::Status Locate(const std::string& crs, const Point2& point) {
    v1::LocateRequest request = LocateRequestFor(point);
    request.set_crs(crs);
    grpc::ClientContext context;
    SetDeadline(&context);
    v1::LocateResponse response;
    return stub_->Locate(&context, request, &response);
  }

  // A plain Locate, the control query.
  void ExpectServing() {
    v1::LocateResponse response;
    grpc::ClientContext context;
    SetDeadline(&context);
    const grpc::Status status =
        stub_->Locate(&context, LocateRequestFor(kOnTheHill), &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    EXPECT_TRUE(response.has_value());
  }

  ScratchDir dir_;
  std::string gpkg_;
  std::string outside_;
  std::unique_ptr<FifoWatch> fifo_;
  std::unique_ptr<LocatordWithHttp> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

void ExpectRefused(const grpc::Status& status, const HostileCrs& row,
                   const std::string& call) {
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
      << call << ", " << row.what << ": " << status.error_message();
  EXPECT_THAT(status.error_message(), HasSubstr("crs: ")) << row.what;
  EXPECT_THAT(status.error_message(), HasSubstr(row.file)) << row.what;
}

TEST_F(LocatordHostileCrsTest, EveryRouteRefusesThemAndTheServerServesOn) {
  for (const HostileCrs& row : Rows()) {
    for (int i = 0; i < kRepeats; ++i) {
      ExpectRefused(Locate(row.crs, {15, 49.65}), row, "Locate");
    }
    {
      v1::LocateBatchRequest batch =
          BatchRequestFor(std::vector<Point2>{{15, 49.65}, {15.01, 49.66}});
      batch.set_crs(row.crs);
      grpc::ClientContext context;
      SetDeadline(&context);
      v1::LocateBatchResponse response;
      ExpectRefused(stub_->LocateBatch(&context, batch, &response), row,
                    "LocateBatch");
    }
    {
      v1::ProfileRequest profile;
      for (const Point2& p : {Point2{14.99, 49.65}, Point2{15.01, 49.66}}) {
        v1::Point* vertex = profile.add_vertices();
        vertex->set_x(p.x);
        vertex->set_y(p.y);
      }
      profile.set_crs(row.crs);
      grpc::ClientContext context;
      SetDeadline(&context);
      v1::ProfileResponse response;
      ExpectRefused(stub_->Profile(&context, profile, &response), row,
                    "Profile");
    }
    {
      grpc::ClientContext context;
      SetDeadline(&context);
      auto stream = stub_->LocateStream(&context);
      v1::LocateRequest request = LocateRequestFor({15, 49.65});
      request.set_crs(row.crs);
      stream->Write(request);
      stream->WritesDone();
      v1::LocateResponse response;
      while (stream->Read(&response)) {
      }
      ExpectRefused(stream->Finish(), row, "LocateStream");
    }
    v1::LocateRequest request = LocateRequestFor({15, 49.65});
    request.set_crs(row.crs);
    for (int i = 0; i < kRepeats; ++i) {
      const HttpReply reply = Post(
          server_->http_port(), "/v1/datasets/default:locate", ToJson(request));
      ExpectError(reply, 400, grpc::StatusCode::INVALID_ARGUMENT, "crs: ");
    }
    ExpectServing();
  }
  EXPECT_FALSE(fifo_->opened()) << "locatord opened " << fifo_->path();
  // A legitimate CRS still works: EPSG:4326 to the hill's UTM zone.
  EXPECT_TRUE(Locate("EPSG:4326", {15, 49.65}).ok());
}

// The reproduction of the issue: three gRPC and two HTTP calls naming
// /dev/ptmx used to hang every later call, and SIGTERM no longer stopped
// the server.
TEST_F(LocatordHostileCrsTest, SigtermStopsItAfterTheIssuesCalls) {
  const std::string crs = "+proj=longlat +ellps=WGS84 +nadgrids=/dev/ptmx";
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(Locate(crs, {15, 49.65}).error_code(),
              grpc::StatusCode::INVALID_ARGUMENT);
  }
  v1::LocateRequest request = LocateRequestFor({15, 49.65});
  request.set_crs(crs);
  for (int i = 0; i < 2; ++i) {
    ExpectError(Post(server_->http_port(), "/v1/datasets/default:locate",
                     ToJson(request)),
                400, grpc::StatusCode::INVALID_ARGUMENT, "/dev/ptmx");
  }
  ExpectServing();
  server_->process().SendSignal(SIGTERM);
  EXPECT_EQ(server_->process().WaitForExit(kGenerousWait), 0);
}

}  // namespace
}  // namespace locator::test
