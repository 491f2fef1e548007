// The bad-input table, part 1: requests. Every way a client can hand a live
// locatord something wrong (or extreme), one row per case: what is sent,
// the server flags it runs against, the exact gRPC status code and a
// substring (compared case-insensitively) the message must contain naming
// the problem. After every row the same server must still answer a normal
// Locate: a bad call never takes the others down. Datasets are part 2
// (bad_dataset_table_test.cc).
//
// Rows that expect OK check the answers against CGAL in-process.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/main/bad_input/abusive_clients.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using Code = grpc::StatusCode;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// What a row's call may use.
struct Env {
  test::ServerProcess& server;
  v1::Locator::Stub& stub;
  const Reference& reference;
  const std::vector<Point2>& queries;
};

struct CallRow {
  std::string name;
  // What is sent, for the failure message.
  std::string input;
  std::vector<std::string> server_flags;
  std::function<grpc::Status(const Env&)> call;
  Code code;
  std::string message;
};

void PrintTo(const CallRow& row, std::ostream* out) { *out << row.input; }

// The servers rows run against, one per distinct flag set.
const std::vector<std::string> kLimits = {"--max-batch-points", "1000"};
const std::vector<std::string> kSmallMessages = {"--max-message-bytes", "8KiB"};
// One batch thread and a 1 ms default deadline: a million points cannot be
// located before it passes.
const std::vector<std::string> kBigBatches = {"--threads", "1",
                                              "--default-deadline-ms", "1"};
const std::vector<std::string> kStreamDeadline = {"--default-deadline-ms",
                                                  "1500"};
// Keepalive enforcement: the default minimum ping interval (10 s) with one
// strike allowed (the client below manages about one ping a second), and
// enforcement switched off.
const std::vector<std::string> kOneStrike = {"--max-ping-strikes", "1"};
const std::vector<std::string> kAnyPings = {"--min-ping-interval-ms", "0",
                                            "--max-ping-strikes", "1"};
const std::vector<std::string> kFewStreams = {"--max-concurrent-streams",
                                              std::to_string(kFloodStreams),
                                              "--default-deadline-ms", "0"};

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return text;
}

// Calls Locate for `q`; when it succeeds, the answer must agree with CGAL.
std::function<grpc::Status(const Env&)> LocateCall(Point2 q) {
  return [q](const Env& env) {
    v1::LocateResponse response;
    const grpc::Status status = LocateOne(env.stub, q, &response);
    if (status.ok()) {
      const LocateResult answer = FromLocateResponse(response);
      EXPECT_EQ(env.reference.Disagreements(std::span(&q, 1),
                                            std::span(&answer, 1), true),
                "");
    }
    return status;
  };
}

grpc::Status SendBatch(const Env& env, const v1::LocateBatchRequest& request,
                       v1::LocateBatchResponse* response,
                       std::chrono::milliseconds deadline) {
  grpc::ClientContext context;
  if (deadline.count() > 0) SetDeadlineFromNow(&context, deadline);
  return env.stub.LocateBatch(&context, request, response);
}

// LocateBatch of the points `make_points` returns (made when the row runs,
// not when the table is listed), with no client deadline unless given; when
// it succeeds, every answer must agree with CGAL.
std::function<grpc::Status(const Env&)> BatchCall(
    std::function<std::vector<Point2>()> make_points,
    std::chrono::milliseconds deadline = std::chrono::milliseconds(0)) {
  return [make_points, deadline](const Env& env) {
    const std::vector<Point2> points = make_points();
    v1::LocateBatchResponse response;
    const grpc::Status status =
        SendBatch(env, BatchRequestFor(points), &response, deadline);
    if (status.ok()) {
      std::vector<LocateResult> answers;
      for (size_t row = 0; row < points.size(); ++row) {
        answers.push_back(FromBatchRow(response, row));
      }
      EXPECT_EQ(env.reference.Disagreements(points, answers, false), "");
    }
    return status;
  };
}

// `n` test queries (repeated as needed).
std::vector<Point2> RepeatedQueries(size_t n) {
  const std::vector<Point2> queries = TestQueries();
  std::vector<Point2> points;
  while (points.size() < n) {
    points.insert(points.end(), queries.begin(), queries.end());
  }
  points.resize(n);
  return points;
}

std::function<std::vector<Point2>()> Queries(size_t n) {
  return [n] { return RepeatedQueries(n); };
}

// `n` test queries with point `index` replaced by `bad`.
std::function<std::vector<Point2>()> QueriesWith(size_t n, size_t index,
                                                 Point2 bad) {
  return [n, index, bad] {
    std::vector<Point2> points = RepeatedQueries(n);
    points[index] = bad;
    return points;
  };
}

std::function<std::vector<Point2>()> Points(std::vector<Point2> points) {
  return [points] { return points; };
}

grpc::Status MismatchedColumns(const Env& env) {
  v1::LocateBatchRequest request =
      BatchRequestFor(std::span<const Point2>(env.queries).subspan(0, 5));
  request.add_xs(1.0);
  v1::LocateBatchResponse response;
  return SendBatch(env, request, &response, std::chrono::seconds(30));
}

grpc::Status EmptyBatch(const Env& env) {
  v1::LocateBatchResponse response;
  const grpc::Status status =
      SendBatch(env, BatchRequestFor({}), &response, std::chrono::seconds(30));
  EXPECT_EQ(response.types_size(), 0);
  EXPECT_EQ(response.vertex_ids_size(), 0);
  EXPECT_EQ(response.total_cost(), 0u);
  return status;
}

// Writes `requests` on one stream, half-closes it and reads every answer:
// there must be `answers`, those before the first bad request.
grpc::Status StreamOf(const Env& env,
                      const std::vector<v1::LocateRequest>& requests,
                      int answers) {
  grpc::ClientContext context;
  auto stream = env.stub.LocateStream(&context);
  for (const v1::LocateRequest& request : requests) stream->Write(request);
  stream->WritesDone();
  int read = 0;
  v1::LocateResponse response;
  while (stream->Read(&response)) ++read;
  EXPECT_EQ(read, answers);
  return stream->Finish();
}

// A stream of two good points, an infinite one and another good one: the
// answers before the bad point arrive, then the stream ends.
grpc::Status StreamWithInfinitePoint(const Env& env) {
  return StreamOf(env,
                  {LocateRequestFor({1.25, 2.5}), LocateRequestFor({3, 4}),
                   LocateRequestFor({kInf, 1}), LocateRequestFor({5, 5})},
                  2);
}

// A Locate whose request has no point at all.
grpc::Status LocateWithoutPoint(const Env& env) {
  grpc::ClientContext context;
  v1::LocateResponse response;
  return env.stub.Locate(&context, v1::LocateRequest(), &response);
}

// A stream of one good point, a request without a point and another good
// point: the first answer arrives, then the stream ends.
grpc::Status StreamWithoutPoint(const Env& env) {
  return StreamOf(env,
                  {LocateRequestFor({1.25, 2.5}), v1::LocateRequest(),
                   LocateRequestFor({3, 4})},
                  1);
}

// A stream the client cancels after five round trips.
grpc::Status StreamCancelledMidway(const Env& env) {
  grpc::ClientContext context;
  auto stream = env.stub.LocateStream(&context);
  for (int k = 0; k < 5; ++k) {
    v1::LocateResponse response;
    EXPECT_TRUE(stream->Write(LocateRequestFor(env.queries[k])) &&
                stream->Read(&response));
  }
  context.TryCancel();
  return stream->Finish();
}

// A stream the client neither writes to nor closes, with no deadline. (A
// watchdog cancels it after a minute, so that a server that never ends it
// fails the row instead of hanging the test.)
grpc::Status IdleStreamWithoutDeadline(const Env& env) {
  grpc::ClientContext context;
  std::promise<void> ended;
  std::thread watchdog([&context, ended = ended.get_future()] {
    if (ended.wait_for(std::chrono::minutes(1)) ==
        std::future_status::timeout) {
      context.TryCancel();
    }
  });
  auto stream = env.stub.LocateStream(&context);
  v1::LocateResponse response;
  EXPECT_FALSE(stream->Read(&response));
  const grpc::Status status = stream->Finish();
  ended.set_value();
  watchdog.join();
  return status;
}

// A million-point batch cancelled once the server is locating it: the
// server stops between blocks instead of finishing the batch.
grpc::Status BatchCancelledMidway(const Env& env) {
  const v1::LocateBatchRequest request =
      BatchRequestFor(RepeatedQueries(1'000'000));
  const uint64_t served_before = GetStats(env.stub).queries_served();
  grpc::ClientContext context;
  // Not the server's 1 ms default: this row is about cancellation.
  SetDeadlineFromNow(&context, std::chrono::minutes(2));
  grpc::Status status;
  std::thread call([&] {
    v1::LocateBatchResponse response;
    status = env.stub.LocateBatch(&context, request, &response);
  });
  auto served = [&] { return GetStats(env.stub).queries_served(); };
  EXPECT_TRUE(test::WaitUntil([&] { return served() > served_before; }));
  context.TryCancel();
  call.join();
  // The server checks between blocks of points and gives up: once it has
  // stopped locating, it must have located only part of the batch. (A server
  // that ignores the cancellation stops only after the whole batch.)
  EXPECT_LT(test::WaitUntilSettled(served) - served_before,
            uint64_t{1'000'000});
  return status;
}

// What every RPC naming an unknown dataset is told: NOT_FOUND and the names
// the server has (one, the default, in this table).
constexpr char kUnknownDataset[] =
    "unknown dataset 'lava'; this server has: default (default)";

// A stream of a good point for the default dataset, then one for 'lava':
// the first answer arrives, then the stream ends.
grpc::Status StreamUnknownDataset(const Env& env) {
  return StreamOf(env,
                  {LocateRequestFor({1.25, 2.5}),
                   LocateRequestFor({3, 4}, "lava"), LocateRequestFor({5, 5})},
                  1);
}

// Calls the unary RPC `rpc` with a request whose `dataset` is 'lava' and
// nothing else (the dataset is resolved before the request is read).
template <typename Request, typename Response>
std::function<grpc::Status(const Env&)> NamingLava(grpc::Status (
    v1::Locator::Stub::*rpc)(grpc::ClientContext*, const Request&, Response*)) {
  return [rpc](const Env& env) {
    grpc::ClientContext context;
    Request request;
    request.set_dataset("lava");
    Response response;
    return (env.stub.*rpc)(&context, request, &response);
  };
}

grpc::Status ReloadUnknownName(const Env& env) {
  v1::ReloadResponse response;
  return Reload(env.stub, "", &response, "lava");
}

// The size of the CRS LocateWithHugeCrs sends.
constexpr size_t kHugeCrsBytes = size_t{10} << 20;

// A Locate naming a 10 MiB CRS (the dataset has none). The refusal quotes a
// short prefix of it: a message that echoed it all would overflow gRPC's
// header limit and reach the client as another error.
grpc::Status LocateWithHugeCrs(const Env& env) {
  v1::LocateRequest request = LocateRequestFor({10.25, 20.5});
  request.set_crs("+proj=longlat +ellps=WGS84 +towgs84=" +
                  std::string(kHugeCrsBytes - 36, '0'));
  grpc::ClientContext context;
  v1::LocateResponse response;
  const grpc::Status status = env.stub.Locate(&context, request, &response);
  EXPECT_LT(status.error_message().size(), 300u) << status.error_message();
  return status;
}

// A Profile across the dataset asking for `samples` evenly spaced samples;
// when it succeeds, they must all be there.
std::function<grpc::Status(const Env&)> ProfileWithSamples(uint32_t samples) {
  return [samples](const Env& env) {
    v1::ProfileRequest request;
    for (const Point2& p : {Point2{10.25, 20.5}, Point2{30.5, 20.25}}) {
      v1::Point* vertex = request.add_vertices();
      vertex->set_x(p.x);
      vertex->set_y(p.y);
    }
    request.set_samples(samples);
    grpc::ClientContext context;
    v1::ProfileResponse response;
    const grpc::Status status = env.stub.Profile(&context, request, &response);
    if (status.ok()) {
      EXPECT_EQ(response.samples_size(), static_cast<int>(samples));
    }
    return status;
  };
}

std::vector<CallRow> CallRows() {
  using std::chrono::milliseconds;
  const double big = 1e308;
  return {
      {"LocateNaN", "Locate (NaN, 1)", kLimits, LocateCall({kNaN, 1}),
       Code::INVALID_ARGUMENT, "non-finite coordinate"},
      {"LocatePlusInf", "Locate (1, +inf)", kLimits, LocateCall({1, kInf}),
       Code::INVALID_ARGUMENT, "non-finite coordinate"},
      {"LocateMinusInf", "Locate (-inf, 0)", kLimits, LocateCall({-kInf, 0}),
       Code::INVALID_ARGUMENT, "non-finite coordinate"},
      {"LocateWithoutPoint", "Locate with no point field", kLimits,
       LocateWithoutPoint, Code::INVALID_ARGUMENT, "point is required"},
      // ±1e308 are finite: answered exactly, outside the hull.
      {"LocatePlus1e308", "Locate (1e308, 1e308)", kLimits,
       LocateCall({big, big}), Code::OK, ""},
      {"LocateMinus1e308", "Locate (-1e308, 5)", kLimits, LocateCall({-big, 5}),
       Code::OK, ""},
      {"BatchNaN", "LocateBatch of 1000, point 987 is (1, NaN)", kLimits,
       BatchCall(QueriesWith(1000, 987, {1, kNaN})), Code::INVALID_ARGUMENT,
       "point 987 has a non-finite coordinate"},
      {"BatchPlusInf", "LocateBatch of 10, point 3 is (+inf, 0)", kLimits,
       BatchCall(QueriesWith(10, 3, {kInf, 0})), Code::INVALID_ARGUMENT,
       "point 3 has a non-finite coordinate"},
      {"BatchMinusInf", "LocateBatch of 10, point 0 is (0, -inf)", kLimits,
       BatchCall(QueriesWith(10, 0, {0, -kInf})), Code::INVALID_ARGUMENT,
       "point 0 has a non-finite coordinate"},
      {"BatchPlusMinus1e308", "LocateBatch of (±1e308, ±1e308) and (1e308, 0)",
       kLimits,
       BatchCall(Points(
           {{big, big}, {-big, -big}, {big, -big}, {-big, big}, {big, 0}})),
       Code::OK, ""},
      {"StreamInf", "LocateStream of 2 good points, then (+inf, 1)", kLimits,
       StreamWithInfinitePoint, Code::INVALID_ARGUMENT,
       "non-finite coordinate"},
      {"StreamWithoutPoint",
       "LocateStream of a good point, then a request with no point", kLimits,
       StreamWithoutPoint, Code::INVALID_ARGUMENT, "point is required"},
      {"EmptyBatch", "LocateBatch with no points", kLimits, EmptyBatch,
       Code::OK, ""},
      {"MismatchedColumns", "LocateBatch with 6 xs and 5 ys", kLimits,
       MismatchedColumns, Code::INVALID_ARGUMENT,
       "xs has 6 values but ys has 5"},
      {"LocateUnknownDataset", "Locate with dataset 'lava'", kLimits,
       NamingLava(&v1::Locator::Stub::Locate), Code::NOT_FOUND,
       kUnknownDataset},
      {"BatchUnknownDataset", "LocateBatch with dataset 'lava'", kLimits,
       NamingLava(&v1::Locator::Stub::LocateBatch), Code::NOT_FOUND,
       kUnknownDataset},
      {"StreamUnknownDataset",
       "LocateStream of a good point, then one with dataset 'lava'", kLimits,
       StreamUnknownDataset, Code::NOT_FOUND, kUnknownDataset},
      {"GetStatsUnknownDataset", "GetStats with dataset 'lava'", kLimits,
       NamingLava(&v1::Locator::Stub::GetStats), Code::NOT_FOUND,
       kUnknownDataset},
      {"GetTopologyUnknownDataset", "GetTopology with dataset 'lava'", kLimits,
       NamingLava(&v1::Locator::Stub::GetTopology), Code::NOT_FOUND,
       kUnknownDataset},
      {"RetuneUnknownDataset", "Retune with dataset 'lava'", kLimits,
       NamingLava(&v1::Locator::Stub::Retune), Code::NOT_FOUND,
       kUnknownDataset},
      {"ReloadUnknownName", "Reload with name 'lava'", kLimits,
       ReloadUnknownName, Code::NOT_FOUND, kUnknownDataset},
      {"LocateWithHugeCrs", "Locate naming a 10 MiB crs", kLimits,
       LocateWithHugeCrs, Code::INVALID_ARGUMENT,
       // Its first 80 bytes, and its size.
       "the request names crs '+proj=longlat +ellps=wgs84 +towgs84=" +
           std::string(44, '0') +
           "...' (10485760 bytes) but the dataset has none"},
      {"ProfileAtDefaultSampleLimit", "Profile of 10^5 samples (the limit)",
       kLimits, ProfileWithSamples(100'000), Code::OK, ""},
      {"ProfileOverDefaultSampleLimit", "Profile of 10^6 samples", kLimits,
       ProfileWithSamples(1'000'000), Code::RESOURCE_EXHAUSTED,
       "a profile of 1000000 samples exceeds this server's limit of 100000 "
       "samples per request (locatord --max-profile-samples)"},
      {"BatchAtPointLimit", "LocateBatch of 1000 points (the limit)", kLimits,
       BatchCall(Queries(1000)), Code::OK, ""},
      {"BatchOverPointLimit", "LocateBatch of 1001 points (limit 1000)",
       kLimits, BatchCall(Queries(1001)), Code::RESOURCE_EXHAUSTED,
       "exceeds this server's limit of 1000 points per batch"},
      {"MessageOverByteLimit",
       "LocateBatch of 1000 points, ~16 KB (limit 8 KiB)", kSmallMessages,
       BatchCall(Queries(1000)), Code::RESOURCE_EXHAUSTED, "larger than max"},
      {"ClientDeadlineShorterThanBatch",
       "LocateBatch of 10^6 points with a 20 ms deadline", kBigBatches,
       BatchCall(Queries(1'000'000), milliseconds(20)), Code::DEADLINE_EXCEEDED,
       "deadline"},
      {"ServerDefaultDeadlineEndsBatch",
       "LocateBatch of 10^6 points without a deadline (server default 1 ms)",
       kBigBatches, BatchCall(Queries(1'000'000)), Code::DEADLINE_EXCEEDED,
       "deadline passed while locating the batch (the server's default of 1 "
       "ms"},
      {"BatchCancelledMidway", "LocateBatch of 10^6 points, cancelled",
       kBigBatches, BatchCancelledMidway, Code::CANCELLED, "cancel"},
      {"StreamCancelledMidway", "LocateStream cancelled after 5 round trips",
       kLimits, StreamCancelledMidway, Code::CANCELLED, "cancel"},
      {"ServerDefaultDeadlineEndsStream",
       "an idle LocateStream without a deadline (server default 1500 ms)",
       kStreamDeadline, IdleStreamWithoutDeadline, Code::DEADLINE_EXCEEDED,
       "deadline passed while streaming (the server's default of 1500 ms"},
      {"StreamsNeverRead",
       "a connection opens --max-concurrent-streams streams and writes "
       "without reading; then one more stream with a 1 s deadline",
       kFewStreams,
       [](const Env& env) { return FloodWithUnreadStreams(env.server); },
       Code::DEADLINE_EXCEEDED, "deadline"},
      {"PingsTooOften",
       "keepalive pings ~1/s on an idle stream (minimum interval 10 s, "
       "--max-ping-strikes 1)",
       kOneStrike, [](const Env& env) { return PingWhileIdle(env.server); },
       Code::UNAVAILABLE, "too many pings"},
      {"PingsAllowedWhenConfigured",
       "the same pings with --min-ping-interval-ms 0: the stream lives to "
       "its 8 s deadline",
       kAnyPings, [](const Env& env) { return PingWhileIdle(env.server); },
       Code::DEADLINE_EXCEEDED, "deadline"},
  };
}

class BadInputTableTest : public ::testing::TestWithParam<CallRow> {
 protected:
  static void SetUpTestSuite() {
    dataset_ = new TestDatasetFile();
    ASSERT_TRUE(Reference::Build(dataset_->path(), &reference_).ok());
    queries_ = new std::vector<Point2>(TestQueries());
  }
  static void TearDownTestSuite() {
    delete servers_;
    servers_ = nullptr;
    reference_.reset();
    delete queries_;
    delete dataset_;
  }

  // The server for `flags`, started on first use and kept for later rows.
  static test::ServerProcess* ServerFor(const std::vector<std::string>& flags) {
    if (servers_ == nullptr) servers_ = new ServerMap();
    std::unique_ptr<test::ServerProcess>& server = (*servers_)[flags];
    if (server == nullptr) {
      const Status started = StartLocatord(dataset_->path(), flags, &server);
      EXPECT_TRUE(started.ok()) << started.ToString();
    }
    return server.get();
  }

  using ServerMap =
      std::map<std::vector<std::string>, std::unique_ptr<test::ServerProcess>>;
  static TestDatasetFile* dataset_;
  static std::unique_ptr<Reference> reference_;
  static std::vector<Point2>* queries_;
  static ServerMap* servers_;
};

TestDatasetFile* BadInputTableTest::dataset_ = nullptr;
std::unique_ptr<Reference> BadInputTableTest::reference_;
std::vector<Point2>* BadInputTableTest::queries_ = nullptr;
BadInputTableTest::ServerMap* BadInputTableTest::servers_ = nullptr;

TEST_P(BadInputTableTest, AnswersWithTheRowsStatusAndKeepsServing) {
  const CallRow& row = GetParam();
  test::ServerProcess* server = ServerFor(row.server_flags);
  ASSERT_NE(server, nullptr);
  auto stub = NewStub(*server);
  const grpc::Status status =
      row.call(Env{*server, *stub, *reference_, *queries_});
  EXPECT_EQ(status.error_code(), row.code)
      << row.input << ": " << status.error_message();
  EXPECT_THAT(Lower(status.error_message()), HasSubstr(Lower(row.message)))
      << row.input;

  // The server keeps serving the others.
  auto other = NewStub(*server);
  v1::LocateResponse response;
  const grpc::Status after = LocateOne(*other, {10.25, 20.5}, &response);
  EXPECT_TRUE(after.ok()) << "after " << row.input << ": "
                          << after.error_message();
  EXPECT_EQ(response.type(), v1::LOCATION_TYPE_FACE);
}

INSTANTIATE_TEST_SUITE_P(Requests, BadInputTableTest,
                         ::testing::ValuesIn(CallRows()),
                         [](const ::testing::TestParamInfo<CallRow>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace locator::test
