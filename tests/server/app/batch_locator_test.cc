// BatchLocator behind an in-process gRPC server: validation, answers in
// input order across shards and blocks, and a batch stopped between blocks
// by cancellation, the default deadline or a failing block. The locate
// function is a fake whose answers name the point they belong to, and which
// holds a block until the call is interrupted, so that every interruption
// happens by construction.

#include "server/app/batch_locator.h"

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <thread>
#include <vector>

#include "locator/v1/locator.grpc.pb.h"
#include "server/grpc/call_context.h"
#include "tests/server/grpc/in_process_server.h"
#include "tests/testing/wait.h"

namespace locator {
namespace {

using Code = grpc::StatusCode;

// The fake's answer for point (x, y): triangle x, cost y.
LocateResult FakeAnswer(const Point2& p) {
  LocateResult result;
  result.type = LocationType::kFace;
  result.triangle_id = static_cast<int64_t>(p.x);
  result.cost.faces_visited = static_cast<uint32_t>(p.y);
  return result;
}

// Serves LocateBatch only, through a BatchLocator over a fake locate
// function. Block `hold_block` (counted over the whole server, -1: none)
// waits until its call is interrupted; a block containing x == fail_x
// fails.
class FakeBatchService final : public v1::Locator::CallbackService {
 public:
  FakeBatchService(size_t threads, size_t max_points,
                   std::chrono::milliseconds default_deadline)
      : default_deadline_(default_deadline),
        batch_locator_(threads, max_points) {}

  grpc::ServerUnaryReactor* LocateBatch(
      grpc::CallbackServerContext* context,
      const v1::LocateBatchRequest* request,
      v1::LocateBatchResponse* response) override {
    grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
    batch_locator_.Run(
        *request,
        [this](std::span<Point2> points, size_t /*first_index*/,
               std::vector<LocateResult>* results,
               const std::function<bool()>& keep_going) {
          return LocateBlock(points, results, keep_going);
        },
        UnaryCallControl(context, reactor, default_deadline_), response);
    return reactor;
  }

  int hold_block = -1;
  double fail_x = -1;
  std::atomic<int> blocks{0};
  std::atomic<size_t> largest_block{0};
  std::promise<void> holding;

 private:
  Status LocateBlock(std::span<const Point2> points,
                     std::vector<LocateResult>* results,
                     const std::function<bool()>& keep_going) {
    size_t largest = largest_block.load();
    while (points.size() > largest &&
           !largest_block.compare_exchange_weak(largest, points.size())) {
    }
    if (blocks++ == hold_block) {
      holding.set_value();
      EXPECT_TRUE(test::WaitUntil([&] { return !keep_going(); }));
    }
    results->clear();
    for (const Point2& p : points) {
      if (p.x == fail_x) return Status::Internal("block failed on purpose");
      results->push_back(FakeAnswer(p));
    }
    return Status::OK();
  }

  const std::chrono::milliseconds default_deadline_;
  BatchLocator batch_locator_;
};

// Points (i, i % 7) for i in [0, n).
v1::LocateBatchRequest NumberedBatch(size_t n) {
  v1::LocateBatchRequest request;
  for (size_t i = 0; i < n; ++i) {
    request.add_xs(static_cast<double>(i));
    request.add_ys(static_cast<double>(i % 7));
  }
  return request;
}

grpc::Status Call(v1::Locator::Stub& stub,
                  const v1::LocateBatchRequest& request,
                  v1::LocateBatchResponse* response,
                  grpc::ClientContext* context = nullptr) {
  grpc::ClientContext own_context;
  return stub.LocateBatch(context != nullptr ? context : &own_context, request,
                          response);
}

TEST(BatchLocatorTest, RejectsBadRequestsBeforeLocating) {
  FakeBatchService service(2, 10, std::chrono::milliseconds(0));
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  v1::LocateBatchResponse response;

  v1::LocateBatchRequest mismatched = NumberedBatch(3);
  mismatched.add_xs(9);
  grpc::Status status = Call(*stub, mismatched, &response);
  EXPECT_EQ(status.error_code(), Code::INVALID_ARGUMENT);
  EXPECT_EQ(status.error_message(),
            "xs has 4 values but ys has 3; they must have the same length");

  status = Call(*stub, NumberedBatch(11), &response);
  EXPECT_EQ(status.error_code(), Code::RESOURCE_EXHAUSTED);
  EXPECT_EQ(status.error_message(),
            "batch of 11 points exceeds this server's limit of 10 points per "
            "batch");

  v1::LocateBatchRequest non_finite = NumberedBatch(5);
  non_finite.set_ys(3, std::numeric_limits<double>::quiet_NaN());
  status = Call(*stub, non_finite, &response);
  EXPECT_EQ(status.error_code(), Code::INVALID_ARGUMENT);
  EXPECT_NE(status.error_message().find("point 3"), std::string::npos)
      << status.error_message();

  EXPECT_EQ(service.blocks.load(), 0);
}

TEST(BatchLocatorTest, AnswersInInputOrderAcrossShardsAndBlocks) {
  // Four shards of several blocks each, the last one ragged.
  const size_t n = 4 * 3 * BatchLocator::kBlockPoints + 17;
  FakeBatchService service(4, n, std::chrono::milliseconds(0));
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  v1::LocateBatchResponse response;
  const grpc::Status status = Call(*stub, NumberedBatch(n), &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(response.triangle_ids_size(), static_cast<int>(n));
  ASSERT_EQ(response.types_size(), static_cast<int>(n));
  ASSERT_EQ(response.costs_size(), static_cast<int>(n));
  uint64_t cost_sum = 0;
  size_t misplaced = 0;
  for (size_t i = 0; i < n; ++i) {
    const int row = static_cast<int>(i);
    if (response.triangle_ids(row) != static_cast<int64_t>(i)) ++misplaced;
    EXPECT_EQ(response.types(row), v1::LOCATION_TYPE_FACE);
    cost_sum += response.costs(row);
  }
  EXPECT_EQ(misplaced, 0u);
  EXPECT_EQ(response.total_cost(), cost_sum);
  EXPECT_GT(cost_sum, 0u);
  // No optional column was asked for.
  EXPECT_EQ(response.vertex_ids_size(), 0);
  EXPECT_EQ(response.values_size(), 0);
  // Located in blocks of at most kBlockPoints, whatever the batch's size.
  EXPECT_LE(service.largest_block.load(), BatchLocator::kBlockPoints);
  EXPECT_GE(service.blocks.load(),
            static_cast<int>(n / BatchLocator::kBlockPoints));
}

TEST(BatchLocatorTest, CancelledCallStopsBetweenBlocks) {
  // One thread: the blocks run one after another on the callback thread.
  FakeBatchService service(1, 1'000'000, std::chrono::milliseconds(0));
  service.hold_block = 0;
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  grpc::ClientContext context;
  std::future<grpc::Status> call = std::async(std::launch::async, [&] {
    v1::LocateBatchResponse response;
    return Call(*stub, NumberedBatch(10 * BatchLocator::kBlockPoints),
                &response, &context);
  });
  service.holding.get_future().wait();
  context.TryCancel();
  EXPECT_EQ(call.get().error_code(), Code::CANCELLED);
  // Shutdown waits for the server's side of the call: after the held block
  // it saw the cancellation and located nothing more.
  server.Shutdown();
  EXPECT_EQ(service.blocks.load(), 1);
}

TEST(BatchLocatorTest, DefaultDeadlineStopsABatchWithoutDeadline) {
  FakeBatchService service(1, 1'000'000, std::chrono::milliseconds(1));
  service.hold_block = 0;
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  v1::LocateBatchResponse response;
  const grpc::Status status =
      Call(*stub, NumberedBatch(10 * BatchLocator::kBlockPoints), &response);
  EXPECT_EQ(status.error_code(), Code::DEADLINE_EXCEEDED)
      << status.error_message();
  // The deadline may pass before the first block or during it (held until
  // then); either way nothing after it is located.
  server.Shutdown();
  EXPECT_LE(service.blocks.load(), 1);
}

TEST(BatchLocatorTest, FailingBlockFailsTheCall) {
  FakeBatchService service(2, 1'000'000, std::chrono::milliseconds(0));
  service.fail_x = 3 * BatchLocator::kBlockPoints + 5;
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  v1::LocateBatchResponse response;
  const grpc::Status status =
      Call(*stub, NumberedBatch(8 * BatchLocator::kBlockPoints), &response);
  EXPECT_EQ(status.error_code(), Code::INTERNAL);
  EXPECT_EQ(status.error_message(), "block failed on purpose");
}

}  // namespace
}  // namespace locator
