// Expensive HTTP/JSON calls against the real locatord: a :grid at the HTTP
// cell limit and a large :locateBatch leave the server's resident memory
// where it was (their replies are freed and returned to the system), a grid
// over the limit is refused without touching memory, and a one-point
// :locate is answered while natural-neighbour grids occupy the expensive
// lane (the server reports them in flight on /metrics; the test then checks
// the order in which the calls finished, not how long they took), and a
// call that finds --http-max-waiting-calls calls queued in its lane is
// refused at once with 503.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/http/http_test_client.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/http/prometheus_text.h"
#include "tests/server/http/status_e2e_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/process_memory.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

// Sanitizer allocators keep freed memory resident (ASAN's quarantine,
// TSAN's shadow), so only a plain build's RSS says what the server keeps;
// tests/server/http/CMakeLists.txt defines this for sanitized builds.
#if defined(LOCATOR_SANITIZED_SERVER)
constexpr bool kRssShowsWhatIsKept = false;
#else
constexpr bool kRssShowsWhatIsKept = true;
#endif

// The HTTP cell limit's default: a 1024 x 1024 grid is at it.
constexpr int kGridSide = 1024;
// A natural-neighbour grid of this side takes seconds: a locate takes
// microseconds.
constexpr int kSlowGridSide = 384;
// A :locateBatch of this many points answers about 4 MB of JSON.
constexpr int kLargeBatchPoints = 100000;

std::string GridBody(int width, int height, const char* interpolation) {
  return R"({"box": {"min_x": 0, "min_y": 0, "max_x": 1, "max_y": 1},
             "width": )" +
         std::to_string(width) + R"(, "height": )" + std::to_string(height) +
         R"(, "interpolation": ")" + interpolation + R"("})";
}

// `points` random points of the unit square with TestValue values, as CSV:
// natural-neighbour interpolation needs values.
void WriteValuedPoints(const std::string& path, int points) {
  std::ofstream out(path);
  out << "x,y,z\n";
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  out.precision(17);
  for (int i = 0; i < points; ++i) {
    const Point2 p{unit(rng), unit(rng)};
    out << p.x << "," << p.y << "," << TestValue(p) << "\n";
  }
}

TEST(HttpLoadTest, BigCallsLeaveResidentMemoryWhereItWas) {
  if (!kRssShowsWhatIsKept) {
    GTEST_SKIP() << "a sanitizer's allocator keeps freed memory resident";
  }
  ScratchDir dir;
  const std::string points = dir.path() + "/valued.csv";
  WriteValuedPoints(points, 20000);
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start(points, {}, &server).ok());
  const int port = server->http_port();
  const std::string grid = "/v1/datasets/default:grid";
  // Every thread that a grid touches has run once.
  ASSERT_EQ(Post(port, grid, GridBody(64, 64, "INTERPOLATION_LINEAR")).status,
            200u);
  const uint64_t before = ResidentBytes(server->process().pid());
  ASSERT_GT(before, 0u);

  const HttpReply finished =
      Post(port, grid, GridBody(kGridSide, kGridSide, "INTERPOLATION_LINEAR"));
  ASSERT_EQ(finished.status, 200u) << finished.body.substr(0, 300);
  // Values, not nodata: ~15 bytes of text per cell.
  EXPECT_GT(finished.body.size(), size_t{10} * kGridSide * kGridSide);
  // The server returns the memory after it has written the reply, which
  // the client may have read whole a moment earlier.
  const pid_t pid = server->process().pid();
  const auto back_where_it_was = [pid, before] {
    return ResidentBytes(pid) < before * 1.2;
  };
  EXPECT_TRUE(WaitUntil(back_where_it_was))
      << "before " << before << ", after a finished grid "
      << ResidentBytes(pid);

  // The issue's 4096 x 4096 grid: refused before anything is rendered.
  ExpectError(
      Post(port, grid, GridBody(4096, 4096, "INTERPOLATION_LINEAR")), 429,
      Code::RESOURCE_EXHAUSTED,
      "a grid of 4096 x 4096 = 16777216 cells exceeds this server's limit of "
      "1048576 cells per request (--http-max-grid-cells");
  EXPECT_TRUE(WaitUntil(back_where_it_was))
      << "before " << before << ", after a refused grid " << ResidentBytes(pid);

  // A large batch: protobuf parses and prints it through many small
  // blocks, which glibc keeps unless they are returned.
  std::ostringstream batch;
  batch << R"({"include_values": true, "xs": [)";
  for (int i = 0; i < kLargeBatchPoints; ++i) {
    batch << (i ? "," : "") << (i % 1000) / 1000.0;
  }
  batch << R"(], "ys": [)";
  for (int i = 0; i < kLargeBatchPoints; ++i) {
    batch << (i ? "," : "") << (i / 1000) / 1000.0;
  }
  batch << "]}";
  const HttpReply located =
      Post(port, "/v1/datasets/default:locateBatch", batch.str());
  ASSERT_EQ(located.status, 200u) << located.body.substr(0, 300);
  EXPECT_TRUE(WaitUntil(back_where_it_was))
      << "before " << before << ", after a large batch " << ResidentBytes(pid);
}

// The value of gauge `name`{lane="LANE"} on /metrics (-1 if absent).
double LaneGauge(int port, const std::string& name, const std::string& lane) {
  HttpReply reply;
  if (!HttpGet(port, "/metrics", &reply).ok()) return -1;
  PrometheusText metrics;
  if (!ParsePrometheusText(reply.body, &metrics).ok()) return -1;
  return metrics.Value(name, {{"lane", lane}}).value_or(-1);
}

TEST(HttpLoadTest, ALocateIsAnsweredWhileGridsFillTheExpensiveLane) {
  ScratchDir dir;
  const std::string points = dir.path() + "/valued.csv";
  WriteValuedPoints(points, 20000);
  std::unique_ptr<LocatordWithHttp> server;
  // A deadline long enough for two natural-neighbour grids in a row.
  ASSERT_TRUE(LocatordWithHttp::Start(
                  points, {"--default-deadline-ms", "600000"}, &server)
                  .ok());
  const int port = server->http_port();

  // Every call takes a number from `finished` as it ends.
  std::atomic<int> finished{0};
  constexpr int kGrids = 2;
  std::vector<int> grid_finished(kGrids, -1);
  std::vector<unsigned> grid_status(kGrids, 0);
  std::vector<std::thread> grids;
  for (int i = 0; i < kGrids; ++i) {
    grids.emplace_back([&, i] {
      const HttpReply reply = Post(port, "/v1/datasets/default:grid",
                                   GridBody(kSlowGridSide, kSlowGridSide,
                                            "INTERPOLATION_NATURAL_NEIGHBOR"));
      grid_finished[i] = finished++;
      grid_status[i] = reply.status;
    });
  }
  // One grid runs, the others wait for the expensive lane's thread.
  const bool lane_full = WaitUntil([port] {
    return LaneGauge(port, "locator_http_calls_running", "expensive") == 1 &&
           LaneGauge(port, "locator_http_calls_waiting", "expensive") ==
               kGrids - 1;
  });
  EXPECT_TRUE(lane_full) << "the grids never filled the expensive lane";

  const HttpReply located = Post(port, "/v1/datasets/default:locate",
                                 R"({"point": {"x": 0.5, "y": 0.5}})");
  const int locate_finished = finished++;
  EXPECT_EQ(located.status, 200u) << located.body;
  for (std::thread& grid : grids) grid.join();

  // The grids that were waiting cannot have ended before the locate (the
  // running one might, by chance); in one queue the locate ends last.
  int grids_before_locate = 0;
  for (int i = 0; i < kGrids; ++i) {
    EXPECT_EQ(grid_status[i], 200u) << "grid " << i;
    if (grid_finished[i] < locate_finished) ++grids_before_locate;
  }
  EXPECT_LE(grids_before_locate, 1);
}

// A call that finds --http-max-waiting-calls calls waiting in its lane is
// refused at once with 503 and Retry-After, as a connection over the limits
// is, and the other lane still answers.
TEST(HttpLoadTest, ACallPastTheWaitingLimitGets503) {
  ScratchDir dir;
  const std::string points = dir.path() + "/valued.csv";
  WriteValuedPoints(points, 20000);
  std::unique_ptr<LocatordWithHttp> server;
  ASSERT_TRUE(LocatordWithHttp::Start(points,
                                      {"--default-deadline-ms", "600000",
                                       "--http-max-waiting-calls", "1"},
                                      &server)
                  .ok());
  const int port = server->http_port();
  // Grids that take seconds. Their answers are not the point: the server
  // is killed when the test ends, which ends their exchanges.
  std::vector<std::thread> grids;
  struct KillThenJoin {
    ~KillThenJoin() {
      server->process().SendSignal(SIGKILL);
      for (std::thread& grid : *grids) grid.join();
    }
    LocatordWithHttp* server;
    std::vector<std::thread>* grids;
  } cleanup{server.get(), &grids};
  const std::string slow_grid =
      GridBody(kSlowGridSide, kSlowGridSide, "INTERPOLATION_NATURAL_NEIGHBOR");
  const auto lane_holds = [port](double running, double waiting) {
    return WaitUntil([=] {
      return LaneGauge(port, "locator_http_calls_running", "expensive") ==
                 running &&
             LaneGauge(port, "locator_http_calls_waiting", "expensive") ==
                 waiting;
    });
  };
  // One grid runs, then one waits: the expensive lane is full.
  for (int i = 0; i < 2; ++i) {
    grids.emplace_back([port, &slow_grid] {
      HttpReply reply;
      static_cast<void>(SendHttp(port, "POST", "/v1/datasets/default:grid",
                                 &reply, slow_grid,
                                 {{"Content-Type", "application/json"}}));
    });
    ASSERT_TRUE(lane_holds(1, i)) << "grid " << i << " never reached the lane";
  }

  const HttpReply refused =
      Post(port, "/v1/datasets/default:profile",
           R"({"vertices": [{"x": 0.1, "y": 0.1}, {"x": 0.9, "y": 0.9}]})");
  ExpectError(refused, 503, Code::UNAVAILABLE,
              "the expensive lane of this server's HTTP API has 1 calls "
              "waiting, its limit (--http-max-waiting-calls); retry");
  EXPECT_EQ(refused.headers.count("retry-after"), 1u);
  EXPECT_TRUE(lane_holds(1, 1));
  const HttpReply located = Post(port, "/v1/datasets/default:locate",
                                 R"({"point": {"x": 0.5, "y": 0.5}})");
  EXPECT_EQ(located.status, 200u) << located.body;
}

}  // namespace
}  // namespace locator::test
