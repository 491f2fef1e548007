// GridStream: serves one Grid call: renders the raster in blocks of rows on
// a worker pool and streams each block as soon as it is done (rows may
// arrive in any order; the first message carries the header), with at most
// kWindowBlocks blocks rendered ahead of the stream.
//
// Blocks are cut as GridRowsPerBlock() (surface_convert.h) says. A
// worker checks before each block whether the client has gone or the
// call's deadline has passed; then the call ends CANCELLED or
// DEADLINE_EXCEEDED once the blocks being rendered are done, with no more
// rows sent.
//
// Owns itself: deletes itself in OnDone(), which gRPC calls after Finish().
// Finish() is called only once no block is being rendered and no write is
// outstanding, so no worker outlives the reactor.
//
// Thread-safety: the workers and gRPC's write reactions run concurrently;
// the call's state is guarded by mu_, and gRPC operations are started
// after mu_ is released.

#ifndef LOCATOR_SERVER_GRID_STREAM_H_
#define LOCATOR_SERVER_GRID_STREAM_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "common/mutex.h"
#include "locator/engine.h"
#include "locator/raster.h"
#include "locator/v1/locator.pb.h"
#include "server/serving/call_deadline.h"
#include "server/serving/worker_pool.h"

namespace locator {

class GridStream final : public grpc::ServerWriteReactor<v1::GridResponse> {
 public:
  static constexpr size_t kWindowBlocks = 8;

  // Streams `spec` (checked) rendered by `engine` (held until done), with
  // `crs_wkt` in the header, rendering on `pool` (at least one thread;
  // not owned). `keep_alive` is held until the call is done (the service's
  // admission).
  GridStream(grpc::CallbackServerContext* context, CallDeadline deadline,
             std::shared_ptr<const Engine> engine, const RasterSpec& spec,
             const std::string& crs_wkt, WorkerPool* pool,
             std::shared_ptr<void> keep_alive);

  void OnWriteDone(bool ok) override EXCLUDES(mu_);
  void OnDone() override { delete this; }

 private:
  // What to do once mu_ is released.
  struct Actions {
    v1::GridResponse* write = nullptr;
    std::optional<grpc::Status> finish;
  };

  void RenderBlock(uint32_t block) EXCLUDES(mu_);
  // Decides the next writes, renders and the finish.
  Actions Pump() REQUIRES(mu_);
  void Run(const Actions& actions);

  grpc::CallbackServerContext* const context_;
  const CallDeadline deadline_;
  const std::shared_ptr<const Engine> engine_;
  const RasterSpec spec_;
  const uint32_t rows_per_block_;
  const uint32_t blocks_;
  WorkerPool* const pool_;
  const std::shared_ptr<void> keep_alive_;
  v1::GridHeader header_;

  Mutex mu_;
  bool header_sent_ GUARDED_BY(mu_) = false;
  uint32_t next_block_ GUARDED_BY(mu_) = 0;
  uint32_t rendering_ GUARDED_BY(mu_) = 0;
  uint32_t written_ GUARDED_BY(mu_) = 0;
  std::deque<std::unique_ptr<v1::GridResponse>> ready_ GUARDED_BY(mu_);
  std::unique_ptr<v1::GridResponse> in_flight_ GUARDED_BY(mu_);
  std::optional<grpc::Status> failure_ GUARDED_BY(mu_);
  bool finished_ GUARDED_BY(mu_) = false;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_GRID_STREAM_H_
