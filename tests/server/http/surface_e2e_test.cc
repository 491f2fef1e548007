// Profiles, grids and interpolations end to end, against the real locatord
// serving the e2e dataset (values on the plane TestValue) beside a
// constrained one (a square boundary with a square hole): over gRPC the
// answers are exact where checked against the plane and CGAL, the grid
// streams every row once, and over HTTP/JSON :profile and :grid answer what
// gRPC answers. Every refusal is a precise status, on both transports, and
// the server keeps serving after it.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using Code = grpc::StatusCode;

constexpr uint64_t kMaxGridCells = 300000;
constexpr uint64_t kMaxCrossings = 5000;
constexpr uint32_t kMaxSamples = 700;
// The e2e dataset's values span about 2 * 150 + 3 * 60.
constexpr double kValueTolerance = 1e-9 * 500;

v1::Point P(double x, double y) {
  v1::Point p;
  p.set_x(x);
  p.set_y(y);
  return p;
}

v1::ProfileRequest ProfileRequestFor(const std::vector<Point2>& line,
                                     uint32_t samples,
                                     const std::string& dataset = "terrain") {
  v1::ProfileRequest request;
  request.set_dataset(dataset);
  for (const Point2& p : line) *request.add_vertices() = P(p.x, p.y);
  request.set_samples(samples);
  return request;
}

v1::GridRequest GridRequestFor(const BoundingBox& box, uint32_t width,
                               uint32_t height,
                               const std::string& dataset = "terrain") {
  v1::GridRequest request;
  request.set_dataset(dataset);
  request.mutable_box()->set_min_x(box.min_x);
  request.mutable_box()->set_min_y(box.min_y);
  request.mutable_box()->set_max_x(box.max_x);
  request.mutable_box()->set_max_y(box.max_y);
  request.set_width(width);
  request.set_height(height);
  request.set_nodata(-1);
  return request;
}

class SurfaceTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dataset_ = new TestDatasetFile();
    scratch_ = new ScratchDir();
    const std::string lake = scratch_->path() + "/lake.wkt";
    std::ofstream(lake) << "POLYGON ((0.1 0.1, 0.9 0.1, 0.9 0.9, 0.1 0.9, "
                           "0.1 0.1), (0.4 0.4, 0.6 0.4, 0.6 0.6, 0.4 0.6, "
                           "0.4 0.4))\n";
    const Status started = LocatordWithHttp::Start(
        "terrain=" + dataset_->path(),
        {"--dataset", "lake=uniform:3000:5+" + lake, "--max-grid-cells",
         std::to_string(kMaxGridCells), "--max-profile-crossings",
         std::to_string(kMaxCrossings), "--max-profile-samples",
         std::to_string(kMaxSamples)},
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
    ASSERT_TRUE(server_->WaitUntilServes("lake").ok());
    ASSERT_TRUE(Reference::Build(dataset_->path(), &reference_).ok());
  }
  static void TearDownTestSuite() {
    server_.reset();
    reference_.reset();
    delete scratch_;
    delete dataset_;
  }
  void SetUp() override {
    ASSERT_NE(server_, nullptr);
    stub_ = server_->NewStub();
  }
  static int port() { return server_->http_port(); }

  static TestDatasetFile* dataset_;
  static ScratchDir* scratch_;
  static std::unique_ptr<LocatordWithHttp> server_;
  static std::unique_ptr<Reference> reference_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

TestDatasetFile* SurfaceTest::dataset_ = nullptr;
ScratchDir* SurfaceTest::scratch_ = nullptr;
std::unique_ptr<LocatordWithHttp> SurfaceTest::server_;
std::unique_ptr<Reference> SurfaceTest::reference_;

TEST_F(SurfaceTest, ProfileIsExactOnThePlaneWithAGapBeforeTheHull) {
  // From 5 units west of the grid's western edge (x = 0), across the grid,
  // then north-east to its top.
  const std::vector<Point2> line = {{-5, 10.5}, {50.3, 30.7}, {55.1, 58.9}};
  const v1::ProfileRequest request = ProfileRequestFor(line, 101);
  grpc::ClientContext context;
  v1::ProfileResponse response;
  ASSERT_TRUE(stub_->Profile(&context, request, &response).ok());
  const double first = std::hypot(55.3, 20.2);
  const double length = first + std::hypot(4.8, 28.2);
  EXPECT_NEAR(response.length(), length, 1e-9);
  ASSERT_GE(response.gaps_size(), 1);
  EXPECT_EQ(response.gaps(0).reason(), v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL);
  EXPECT_NEAR(response.gaps(0).from_distance(), 0, 1e-12);
  EXPECT_NEAR(response.gaps(0).to_distance(), 5 * first / 55.3, 1e-9);
  uint64_t crossings = 0;
  double last = 0;
  for (const v1::ProfilePoint& p : response.breakpoints()) {
    EXPECT_GE(p.distance(), last);
    last = p.distance();
    crossings += p.kind() == v1::PROFILE_POINT_KIND_EDGE_CROSSING ||
                 p.kind() == v1::PROFILE_POINT_KIND_MESH_VERTEX;
    if (p.distance() > response.gaps(0).to_distance() + 1e-9) {
      ASSERT_TRUE(p.has_value()) << p.ShortDebugString();
      EXPECT_NEAR(p.value(), TestValue({p.point().x(), p.point().y()}),
                  kValueTolerance);
    }
  }
  EXPECT_EQ(response.crossings(), crossings);
  // The grid's unit squares: the line crosses at least one edge per unit
  // of x and of y it spans.
  EXPECT_GT(crossings, 55u + 20 + 4 + 28);
  ASSERT_EQ(response.samples_size(), 101);
  for (int i = 0; i < 101; ++i) {
    const v1::ProfilePoint& s = response.samples(i);
    EXPECT_NEAR(s.distance(), length * i / 100, 1e-9);
    if (s.distance() > response.gaps(0).to_distance() + 1e-9) {
      ASSERT_TRUE(s.has_value());
      EXPECT_NEAR(s.value(), TestValue({s.point().x(), s.point().y()}),
                  kValueTolerance);
    } else {
      EXPECT_FALSE(s.has_value());
    }
  }
}

TEST_F(SurfaceTest, ProfileOverHttpAnswersWhatGrpcAnswers) {
  const v1::ProfileRequest request =
      ProfileRequestFor({{3.5, 2.25}, {40.75, 51.5}, {120, 7}}, 17);
  grpc::ClientContext context;
  v1::ProfileResponse expected;
  ASSERT_TRUE(stub_->Profile(&context, request, &expected).ok());
  const HttpReply reply =
      Post(port(), "/v1/datasets/terrain:profile", ToJson(request));
  ASSERT_EQ(reply.status, 200u) << reply.body.substr(0, 300);
  EXPECT_TRUE(SameProto(FromJson<v1::ProfileResponse>(reply.body), expected));
}

TEST_F(SurfaceTest, GridStreamsEveryRowAndAgreesWithCgal) {
  // 3 messages of at most 2^17 values; the box reaches beyond the hull.
  const v1::GridRequest request =
      GridRequestFor(BoundingBox{-3, -2, 155, 62}, 4096, 70);
  v1::GridResponse grid;
  int messages = 0;
  const grpc::Status status = StreamGrid(*stub_, request, &grid, &messages);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(messages, 3);
  const v1::GridHeader& h = grid.header();
  EXPECT_EQ(h.width(), 4096u);
  EXPECT_EQ(h.height(), 70u);
  EXPECT_DOUBLE_EQ(h.cell_width(), 158.0 / 4096);
  EXPECT_DOUBLE_EQ(h.cell_height(), 64.0 / 70);
  EXPECT_EQ(h.nodata(), -1);
  ASSERT_EQ(grid.values_size(), 4096 * 70);
  int valued = 0;
  for (int i = 0; i < grid.values_size(); i += 7) {
    const uint32_t col = i % 4096, row = i / 4096;
    const Point2 q{h.box().min_x() + (col + 0.5) * h.cell_width(),
                   h.box().max_y() - (row + 0.5) * h.cell_height()};
    const LocateResult want = reference_->Locate(q);
    if (want.has_value) {
      ++valued;
      EXPECT_NEAR(grid.values(i), want.value, kValueTolerance)
          << col << "," << row;
    } else {
      EXPECT_EQ(grid.values(i), -1) << col << "," << row;
    }
  }
  EXPECT_GT(valued, 10000);
}

TEST_F(SurfaceTest, GridOverHttpAnswersWhatGrpcStreams) {
  const v1::GridRequest request =
      GridRequestFor(BoundingBox{0.05, 0.05, 0.95, 0.95}, 64, 48, "lake");
  v1::GridResponse expected;
  ASSERT_TRUE(StreamGrid(*stub_, request, &expected).ok());
  const HttpReply reply =
      Post(port(), "/v1/datasets/lake:grid", ToJson(request));
  ASSERT_EQ(reply.status, 200u) << reply.body.substr(0, 300);
  EXPECT_TRUE(SameProto(FromJson<v1::GridResponse>(reply.body), expected));
  // The hole's centre is nodata, and so are the cells outside the boundary.
  EXPECT_EQ(expected.values(24 * 64 + 32), -1);
  EXPECT_EQ(expected.values(0), -1);
}

TEST_F(SurfaceTest, CancellingAGridMidStreamKeepsTheServerServing) {
  const v1::GridRequest request =
      GridRequestFor(BoundingBox{0, 0, 150, 60}, 4096, 73);
  grpc::ClientContext context;
  auto reader = stub_->Grid(&context, request);
  v1::GridResponse message;
  ASSERT_TRUE(reader->Read(&message));
  EXPECT_TRUE(message.has_header());
  context.TryCancel();
  while (reader->Read(&message)) {
  }
  EXPECT_EQ(reader->Finish().error_code(), Code::CANCELLED);
  v1::LocateResponse located;
  EXPECT_TRUE(LocateOne(*stub_, {10.25, 20.5}, &located, "terrain").ok());
}

TEST_F(SurfaceTest, InterpolationsOverLocateBatchAndStream) {
  const std::vector<Point2> queries = {{10.3, 20.7}, {100.2, 33.3}, {5, 5}};
  for (const v1::Interpolation how :
       {v1::INTERPOLATION_NATURAL_NEIGHBOR, v1::INTERPOLATION_LINEAR}) {
    for (const Point2& q : queries) {
      v1::LocateRequest request = LocateRequestFor(q, "terrain");
      request.set_interpolation(how);
      grpc::ClientContext context;
      v1::LocateResponse response;
      ASSERT_TRUE(stub_->Locate(&context, request, &response).ok());
      ASSERT_TRUE(response.has_value());
      // Both reproduce the plane the values lie on.
      EXPECT_NEAR(response.value(), TestValue(q), kValueTolerance);
    }
  }
  v1::LocateBatchRequest batch = BatchRequestFor(queries);
  batch.set_dataset("terrain");
  batch.set_interpolation(v1::INTERPOLATION_NEAREST);
  grpc::ClientContext context;
  v1::LocateBatchResponse answers;
  ASSERT_TRUE(stub_->LocateBatch(&context, batch, &answers).ok());
  // (5, 5) is a vertex of the exact grid: every interpolation gives its
  // value; (10.3, 20.7)'s nearest corner is (10, 21).
  EXPECT_EQ(answers.values(2), TestValue({5, 5}));
  EXPECT_EQ(answers.values(0), TestValue({10, 21}));
}

// One refusal: the request, the transport's answer, and the substring.
struct Refusal {
  std::string name;
  std::function<grpc::Status(v1::Locator::Stub&)> grpc_call;
  // The HTTP method path and body, for the same request.
  std::string http_target;
  std::string http_body;
  Code code;
  std::string message;
};

void PrintTo(const Refusal& row, std::ostream* out) { *out << row.name; }

std::vector<Refusal> Refusals() {
  const auto profile = [](v1::ProfileRequest request) {
    return [request](v1::Locator::Stub& stub) {
      grpc::ClientContext context;
      v1::ProfileResponse response;
      return stub.Profile(&context, request, &response);
    };
  };
  const auto grid = [](v1::GridRequest request) {
    return [request](v1::Locator::Stub& stub) {
      v1::GridResponse whole;
      return StreamGrid(stub, request, &whole);
    };
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const BoundingBox box{0, 0, 1, 1};
  std::vector<Refusal> rows;
  auto add = [&rows](std::string name, auto call, const auto& request,
                     const std::string& method, Code code,
                     std::string message) {
    rows.push_back({std::move(name), call(request),
                    "/v1/datasets/" + request.dataset() + ":" + method,
                    ToJson(request), code, std::move(message)});
  };
  add("ProfileOfOnePoint", profile, ProfileRequestFor({{1, 1}}, 0), "profile",
      Code::INVALID_ARGUMENT, "it needs at least 2");
  add("ProfileWithNaN", profile, ProfileRequestFor({{1, 1}, {nan, 2}}, 0),
      "profile", Code::INVALID_ARGUMENT, "line point 1 is not finite");
  // A zigzag across the grid, about 120 crossings a leg.
  std::vector<Point2> zigzag;
  for (int leg = 0; leg < 58; ++leg) {
    zigzag.push_back({leg % 2 == 0 ? 0.5 : 58.5, leg + 0.25});
  }
  add("ProfileOverCrossingLimit", profile, ProfileRequestFor(zigzag, 0),
      "profile", Code::RESOURCE_EXHAUSTED,
      "crosses more than " + std::to_string(kMaxCrossings) + " triangle edges");
  const std::string over_samples =
      " samples exceeds this server's limit of " + std::to_string(kMaxSamples) +
      " samples per request (locatord --max-profile-samples)";
  add("ProfileOverSampleLimit", profile,
      ProfileRequestFor({{1, 1}, {2, 2}}, kMaxSamples + 1), "profile",
      Code::RESOURCE_EXHAUSTED,
      "a profile of " + std::to_string(kMaxSamples + 1) + over_samples);
  // Refused before anything is allocated (this one once ended in bad_alloc).
  add("ProfileOfFourBillionSamples", profile,
      ProfileRequestFor({{1, 1}, {2, 2}}, 4'000'000'000), "profile",
      Code::RESOURCE_EXHAUSTED, "a profile of 4000000000" + over_samples);
  // Every vertex enters at least one triangle.
  std::vector<Point2> long_line(kMaxCrossings + 1, Point2{1, 1});
  add("ProfileLineOverCrossingLimit", profile, ProfileRequestFor(long_line, 0),
      "profile", Code::RESOURCE_EXHAUSTED,
      "a profile line of " + std::to_string(kMaxCrossings + 1) +
          " vertices enters more triangles than this server's limit of " +
          std::to_string(kMaxCrossings));
  add("ProfileOfUnknownDataset", profile,
      ProfileRequestFor({{1, 1}, {2, 2}}, 0, "lava"), "profile",
      Code::NOT_FOUND, "lava");
  v1::ProfileRequest natural =
      ProfileRequestFor({{0.2, 0.2}, {0.8, 0.3}}, 0, "lake");
  natural.set_interpolation(v1::INTERPOLATION_NATURAL_NEIGHBOR);
  add("ProfileNaturalNeighborOnConstraints", profile, natural, "profile",
      Code::INVALID_ARGUMENT, "needs a Delaunay triangulation");
  v1::ProfileRequest unknown = ProfileRequestFor({{1, 1}, {2, 2}}, 0);
  unknown.set_interpolation(static_cast<v1::Interpolation>(99));
  add("ProfileUnknownInterpolation", profile, unknown, "profile",
      Code::INVALID_ARGUMENT, "unknown interpolation 99");
  v1::GridRequest no_box = GridRequestFor(box, 4, 4);
  no_box.clear_box();
  add("GridWithoutBox", grid, no_box, "grid", Code::INVALID_ARGUMENT,
      "box is required");
  add("GridEmptyBox", grid, GridRequestFor(BoundingBox{1, 0, 1, 1}, 4, 4),
      "grid", Code::INVALID_ARGUMENT, "min_x < max_x");
  add("GridWidthWithoutHeight", grid, GridRequestFor(box, 4, 0), "grid",
      Code::INVALID_ARGUMENT, "width and height >= 1");
  v1::GridRequest both = GridRequestFor(box, 4, 4);
  both.set_cell_size(0.25);
  add("GridSizeAndCellSize", grid, both, "grid", Code::INVALID_ARGUMENT,
      "not both");
  add("GridWithoutSize", grid, GridRequestFor(box, 0, 0), "grid",
      Code::INVALID_ARGUMENT, "not neither");
  v1::GridRequest negative = GridRequestFor(box, 0, 0);
  negative.set_cell_size(-1);
  add("GridNegativeCellSize", grid, negative, "grid", Code::INVALID_ARGUMENT,
      "cell_size must be finite and positive");
  add("GridOverCellLimit", grid, GridRequestFor(box, 600, 600), "grid",
      Code::RESOURCE_EXHAUSTED, "limit of " + std::to_string(kMaxGridCells));
  v1::GridRequest tiny_cells = GridRequestFor(box, 0, 0);
  tiny_cells.set_cell_size(1e-3);
  add("GridCellSizeOverCellLimit", grid, tiny_cells, "grid",
      Code::RESOURCE_EXHAUSTED, "1000 x 1000 = 1000000 cells");
  // 1e-300 and the columns it makes (1 / 1e-300 in double) read in their
  // shortest exact form, not as 300 digits.
  v1::GridRequest minute_cells = GridRequestFor(box, 0, 0);
  minute_cells.set_cell_size(1e-300);
  add("GridOfMinuteCellSize", grid, minute_cells, "grid",
      Code::RESOURCE_EXHAUSTED,
      "cell_size 1e-300 makes a grid of 9.999999999999999e+299 x "
      "9.999999999999999e+299 cells");
  v1::GridRequest natural_grid = GridRequestFor(box, 4, 4, "lake");
  natural_grid.set_interpolation(v1::INTERPOLATION_NATURAL_NEIGHBOR);
  add("GridNaturalNeighborOnConstraints", grid, natural_grid, "grid",
      Code::INVALID_ARGUMENT, "needs a Delaunay triangulation");
  v1::LocateRequest locate = LocateRequestFor({1, 1}, "terrain");
  locate.set_interpolation(static_cast<v1::Interpolation>(7));
  add(
      "LocateUnknownInterpolation",
      [](v1::LocateRequest request) {
        return [request](v1::Locator::Stub& stub) {
          grpc::ClientContext context;
          v1::LocateResponse response;
          return stub.Locate(&context, request, &response);
        };
      },
      locate, "locate", Code::INVALID_ARGUMENT, "unknown interpolation 7");
  return rows;
}

// The HTTP status each of the table's codes travels as.
unsigned ExpectedHttpStatus(Code code) {
  switch (code) {
    case Code::INVALID_ARGUMENT:
      return 400;
    case Code::NOT_FOUND:
      return 404;
    case Code::RESOURCE_EXHAUSTED:
      return 429;
    default:
      ADD_FAILURE() << "no HTTP status listed for code " << code;
      return 0;
  }
}

class SurfaceRefusalTest : public SurfaceTest,
                           public ::testing::WithParamInterface<Refusal> {};

TEST_P(SurfaceRefusalTest, IsThePreciseStatusOverGrpcAndHttp) {
  const Refusal& row = GetParam();
  const grpc::Status status = row.grpc_call(*stub_);
  EXPECT_EQ(status.error_code(), row.code) << status.error_message();
  EXPECT_THAT(status.error_message(), HasSubstr(row.message));
  // JSON cannot carry an unknown enum number; the other rows go over HTTP.
  if (row.name.find("UnknownInterpolation") == std::string::npos) {
    const HttpReply reply = Post(port(), row.http_target, row.http_body);
    ExpectError(reply, ExpectedHttpStatus(row.code), row.code, row.message);
  }
  v1::LocateResponse located;
  EXPECT_TRUE(LocateOne(*stub_, {10.25, 20.5}, &located, "terrain").ok());
}

INSTANTIATE_TEST_SUITE_P(Rows, SurfaceRefusalTest,
                         ::testing::ValuesIn(Refusals()),
                         [](const ::testing::TestParamInfo<Refusal>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace locator::test
