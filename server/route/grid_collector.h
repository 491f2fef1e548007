// GridCollector: a Grid the router (locatord --route) reads whole from one
// shard, for an answer that is one message: the HTTP/JSON :grid, whose
// GridResponse holds the header and every row. Any shard answers a grid
// whole; the router asks the one holding the grid's centre.
//
// A grid of more than `max_cells` cells (or rows) is refused with
// RESOURCE_EXHAUSTED (naming the limit and --http-max-grid-cells, as a
// server's :grid is) as soon as the shard's header says so, and the
// shard's call is cancelled.
// A stream that breaks its own header (rows past the height, twice, or
// missing) ends the call with INTERNAL naming the shard. The shard's status
// otherwise ends it, its message naming the shard.
//
// Owns itself: deletes itself once the shard's call is done. Thread-safety:
// gRPC runs its reactions one at a time (one read is outstanding).

#ifndef LOCATOR_SERVER_ROUTE_GRID_COLLECTOR_H_
#define LOCATOR_SERVER_ROUTE_GRID_COLLECTOR_H_

#include <grpcpp/grpcpp.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "locator/v1/locator.grpc.pb.h"
#include "server/route/shard_topology.h"

namespace locator {

class GridCollector final : public grpc::ClientReadReactor<v1::GridResponse> {
 public:
  // Reads `request`'s grid from shard `shard` of `topology` (which must
  // outlive the call) on `context` into *whole, then calls `finish`.
  // `request` and `whole` must live until then.
  static void Start(const ShardTopology* topology, size_t shard,
                    std::shared_ptr<grpc::ClientContext> context,
                    const v1::GridRequest* request, uint64_t max_cells,
                    v1::GridResponse* whole,
                    std::function<void(grpc::Status)> finish);

  void OnReadDone(bool ok) override;
  void OnDone(const grpc::Status& status) override;

 private:
  GridCollector(const ShardTopology* topology, size_t shard,
                std::shared_ptr<grpc::ClientContext> context,
                uint64_t max_cells, v1::GridResponse* whole,
                std::function<void(grpc::Status)> finish);

  // Takes message_ into *whole_; the refusal that ends the call, if any.
  std::optional<grpc::Status> Take();
  // `what` the shard's stream did wrong, as the status that ends the call.
  grpc::Status Broken(const std::string& what) const;

  const ShardTopology* const topology_;
  const size_t shard_;
  const std::shared_ptr<grpc::ClientContext> context_;
  const uint64_t max_cells_;
  v1::GridResponse* const whole_;
  const std::function<void(grpc::Status)> finish_;
  v1::GridResponse message_;
  bool header_seen_ = false;
  std::vector<bool> row_seen_;  // sized by the header
  uint64_t rows_seen_ = 0;
  std::optional<grpc::Status> refusal_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_GRID_COLLECTOR_H_
