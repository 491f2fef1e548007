// GridCollector against a scripted shard: a grid read whole when the
// shard's stream keeps its header; INTERNAL naming the shard when the
// stream breaks it (no header first, a header twice, rows it does not
// have, a row twice, rows missing); RESOURCE_EXHAUSTED for a grid past
// the limit; and the shard's own status, naming it, when it fails.

#include "server/route/grid_collector.h"

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/channel_options.h"
#include "locator/v1/locator.grpc.pb.h"
#include "server/route/shard_topology.h"

namespace locator {
namespace {

using ::testing::HasSubstr;

// Writes its script's messages in order, then ends with its status.
class ScriptedGrid final : public grpc::ServerWriteReactor<v1::GridResponse> {
 public:
  ScriptedGrid(std::vector<v1::GridResponse> messages, grpc::Status end)
      : messages_(std::move(messages)), end_(std::move(end)) {
    WriteNext();
  }
  void OnWriteDone(bool ok) override {
    if (ok) {
      WriteNext();
    } else {
      Finish(grpc::Status::CANCELLED);
    }
  }
  void OnDone() override { delete this; }

 private:
  void WriteNext() {
    if (next_ < messages_.size()) {
      StartWrite(&messages_[next_++]);
    } else {
      Finish(end_);
    }
  }

  std::vector<v1::GridResponse> messages_;
  const grpc::Status end_;
  size_t next_ = 0;
};

// A shard whose Grid plays `script` and ends with `end`.
class ScriptedShard final : public v1::Locator::CallbackService {
 public:
  grpc::ServerWriteReactor<v1::GridResponse>* Grid(
      grpc::CallbackServerContext*, const v1::GridRequest*) override {
    return new ScriptedGrid(script, end);
  }

  std::vector<v1::GridResponse> script;
  grpc::Status end;
};

v1::GridResponse Header(uint32_t width, uint32_t height) {
  v1::GridResponse message;
  message.mutable_header()->set_width(width);
  message.mutable_header()->set_height(height);
  return message;
}

v1::GridResponse Rows(uint32_t first_row, uint32_t rows, int values) {
  v1::GridResponse message;
  message.set_first_row(first_row);
  message.set_rows(rows);
  for (int v = 0; v < values; ++v) {
    message.add_values(100 * first_row + v);
  }
  return message;
}

class GridCollectorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grpc::ServerBuilder builder;
    int port = 0;
    builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(),
                             &port);
    builder.RegisterService(&shard_);
    server_ = builder.BuildAndStart();
    ASSERT_NE(server_, nullptr);
    target_ = "127.0.0.1:" + std::to_string(port);
    topology_ = std::make_unique<ShardTopology>(
        std::vector<std::string>{target_}, ChannelOptions{},
        std::chrono::seconds(10));
  }
  void TearDown() override {
    topology_.reset();
    server_->Shutdown();
  }

  // Collects the scripted grid (6 cells at most) into *whole.
  grpc::Status Collect(std::vector<v1::GridResponse> script, grpc::Status end,
                       v1::GridResponse* whole) {
    shard_.script = std::move(script);
    shard_.end = std::move(end);
    auto context = std::make_unique<grpc::ClientContext>();
    context->set_deadline(std::chrono::system_clock::now() +
                          std::chrono::seconds(30));
    std::promise<grpc::Status> finished;
    GridCollector::Start(topology_.get(), 0,
                         topology_->NewContext(std::move(context)), &request_,
                         /*max_cells=*/6, whole,
                         [&finished](grpc::Status status) {
                           finished.set_value(std::move(status));
                         });
    return finished.get_future().get();
  }

  ScriptedShard shard_;
  std::unique_ptr<grpc::Server> server_;
  std::string target_;
  std::unique_ptr<ShardTopology> topology_;
  const v1::GridRequest request_;
};

TEST_F(GridCollectorTest, AGridThatKeepsItsHeaderIsReadWhole) {
  v1::GridResponse whole;
  // Rows in any order, in messages of any size.
  const grpc::Status status = Collect(
      {Header(3, 2), Rows(1, 1, 3), Rows(0, 1, 3)}, grpc::Status::OK, &whole);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(whole.header().width(), 3u);
  EXPECT_EQ(whole.rows(), 2u);
  EXPECT_THAT(whole.values(), ::testing::ElementsAre(0, 1, 2, 100, 101, 102));
}

TEST_F(GridCollectorTest, AStreamThatBreaksItsHeaderIsInternalNamingTheShard) {
  const struct {
    std::vector<v1::GridResponse> script;
    const char* said;
  } broken[] = {
      {{Rows(0, 1, 3)}, "does not start with its header, once"},
      {{Header(3, 2), Header(3, 2)}, "does not start with its header, once"},
      {{Header(3, 2), Rows(1, 2, 6)}, "sends rows its header does not have"},
      {{Header(3, 2), Rows(0, 1, 2)}, "sends rows its header does not have"},
      {{Header(3, 2), Rows(1, 1, 3), Rows(1, 1, 3)}, "sends row 1 twice"},
      {{Header(3, 2), Rows(0, 1, 3)}, "ends short of its header's rows"},
      {{}, "ends short of its header's rows"},
  };
  for (const auto& [script, said] : broken) {
    v1::GridResponse whole;
    const grpc::Status status = Collect(script, grpc::Status::OK, &whole);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INTERNAL) << said;
    EXPECT_EQ(status.error_message(),
              "shard 0 (" + target_ + "): its grid stream " + said);
  }
}

TEST_F(GridCollectorTest, AGridPastTheLimitIsRefusedAtItsHeader) {
  for (const v1::GridResponse& header :
       {Header(7, 1), Header(3, 3), Header(0, 4000000000u),
        Header(4000000000u, 4000000000u)}) {
    v1::GridResponse whole;
    const grpc::Status status =
        Collect({header, Rows(0, 1, 3)}, grpc::Status::OK, &whole);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED)
        << header.ShortDebugString();
    EXPECT_THAT(status.error_message(), HasSubstr("--http-max-grid-cells"));
  }
}

TEST_F(GridCollectorTest, AShardsFailureEndsTheCallNamingTheShard) {
  v1::GridResponse whole;
  const grpc::Status status = Collect(
      {Header(3, 2), Rows(0, 1, 3)},
      grpc::Status(grpc::StatusCode::UNAVAILABLE, "going away"), &whole);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAVAILABLE);
  EXPECT_EQ(status.error_message(), "shard 0 (" + target_ + "): going away");
}

}  // namespace
}  // namespace locator
