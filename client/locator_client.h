// LocatorClient: the one client of locator.v1.Locator that the `locator` CLI
// and the `locator-load` driver share (the channel it talks over is built by
// common/channel_options.h).
//
// Owns a Locator stub and a health checker on a shared channel, the per-call
// deadline and the request scope. Every call it starts, blocking or
// callback, gets a deadline before it is sent: a stalled server can never
// hang a client. Every request it sends carries its scope: the dataset, and
// where the request has them, the CRS and the interpolation.
//
// Thread-safety: a LocatorClient is thread-safe (gRPC stubs are). For the
// callback calls the caller owns the context and messages and keeps them
// alive until the completion runs.

#ifndef LOCATOR_CLIENT_LOCATOR_CLIENT_H_
#define LOCATOR_CLIENT_LOCATOR_CLIENT_H_

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "client/health_check.h"
#include "common/channel_options.h"
#include "locator/geometry.h"
#include "locator/v1/locator.grpc.pb.h"

namespace locator {

class ShardRoutes;

// Sets `context`'s deadline to `timeout` from now.
void SetDeadlineFromNow(grpc::ClientContext* context,
                        std::chrono::milliseconds timeout);

// "<CODE>: <message>", as the CLI and the load driver print a failed call.
std::string DescribeRpcError(const grpc::Status& status);

// Which optional columns LocateBatch asks the server to fill.
struct BatchColumns {
  bool vertex_ids = false;
  bool barycentric = false;
  bool values = false;
};

// Sets the include_* flags of `request` that ask for `columns`.
void RequestColumns(const BatchColumns& columns,
                    v1::LocateBatchRequest* request);

// What a client's requests are about beyond their own content.
struct RequestScope {
  // The dataset every request goes to (its `dataset` field, ReloadRequest's
  // `name`); "": the server's default dataset.
  std::string dataset;
  // The CRS of the points of Locate, LocateBatch, LocateStream and Profile
  // requests; "": the dataset's own coordinates.
  std::string crs;
  // How Locate, LocateBatch, Profile and Grid interpolate values.
  v1::Interpolation interpolation = v1::INTERPOLATION_UNSPECIFIED;
};

// Sets the fields of `request` that `scope` decides.
void ApplyScope(const RequestScope& scope, v1::LocateRequest* request);
void ApplyScope(const RequestScope& scope, v1::LocateBatchRequest* request);
void ApplyScope(const RequestScope& scope, v1::ProfileRequest* request);
void ApplyScope(const RequestScope& scope, v1::GridRequest* request);

class LocatorClient {
 public:
  using Completion = std::function<void(grpc::Status)>;
  using StreamReactor =
      grpc::ClientBidiReactor<v1::LocateRequest, v1::LocateResponse>;
  // Takes one message of a Grid stream; false stops the stream.
  using GridConsumer = std::function<bool(const v1::GridResponse& message)>;

  // A client on `channel` whose calls each get `deadline` to complete and
  // whose requests carry `scope`.
  LocatorClient(std::shared_ptr<grpc::Channel> channel,
                std::chrono::milliseconds deadline, RequestScope scope = {});
  ~LocatorClient();

  // From now on sends Locate and LocateBatch straight to the shards of the
  // scope's dataset, as its GetTopology (asked through this client) says:
  // each point to the shard serving its tile, a batch split by shard and
  // merged in input order (ShardRoutes), over channels made with `channel`
  // (a shard's target replacing its own). A dataset on one server keeps
  // going through this client. The GetTopology call's error, or
  // FAILED_PRECONDITION for a topology without every tile's shard. Call it
  // before any call starts.
  grpc::Status RouteByTopology(const ChannelOptions& channel);

  std::chrono::milliseconds deadline() const { return deadline_; }
  const RequestScope& scope() const { return scope_; }

  // Blocking calls.
  // Locates one point.
  grpc::Status Locate(const Point2& point, v1::LocateResponse* response);
  // Locates points (xs[i], ys[i]); xs and ys must have the same size.
  grpc::Status LocateBatch(std::span<const double> xs,
                           std::span<const double> ys,
                           const BatchColumns& columns,
                           v1::LocateBatchResponse* response);
  // Reads the server's statistics.
  grpc::Status GetStats(v1::GetStatsResponse* response);
  // Re-tunes the server now.
  grpc::Status Retune(v1::RetuneResponse* response);
  // Makes the server load `spec` ("": the scope's dataset's configured one)
  // into the scope's dataset and serve it.
  grpc::Status Reload(const std::string& spec, v1::ReloadResponse* response);
  // Lists the server's datasets.
  grpc::Status ListDatasets(v1::ListDatasetsResponse* response);
  // The surface along the polyline `vertices`, with `samples` evenly spaced
  // points.
  grpc::Status Profile(std::span<const Point2> vertices, uint32_t samples,
                       v1::ProfileResponse* response);
  // Renders `request` (box, size, nodata; the scope fills the rest) and
  // hands each message of the stream to `consume`, in order, on this
  // thread. The deadline covers the whole stream. When `consume` returns
  // false the call is cancelled and CANCELLED is returned.
  grpc::Status Grid(v1::GridRequest request, const GridConsumer& consume);
  // Asks the standard health service about the server as a whole.
  grpc::Status CheckHealth(HealthStatus* status);

  // Callback calls: start and return at once; `done` runs on a gRPC thread.
  // Starts a Locate of `request`, after applying the scope to it.
  void StartLocate(grpc::ClientContext* context, v1::LocateRequest* request,
                   v1::LocateResponse* response, Completion done);
  // Starts a LocateBatch of `request`, after applying the scope to it.
  // Routed, its parts get contexts of their own (same deadline) and
  // `context` is not used.
  void StartLocateBatch(grpc::ClientContext* context,
                        v1::LocateBatchRequest* request,
                        v1::LocateBatchResponse* response, Completion done);
  // Starts a LocateStream driven by `reactor`, which must still call
  // StartCall() and apply scope() to the requests it writes. A stream is
  // one call, so it gets one deadline for its whole life:
  // `stream_deadline`, not the per-call deadline.
  void StartLocateStream(grpc::ClientContext* context,
                         std::chrono::system_clock::time_point stream_deadline,
                         StreamReactor* reactor);

 private:
  std::unique_ptr<v1::Locator::Stub> stub_;
  std::unique_ptr<ShardRoutes> routes_;  // set by RouteByTopology
  HealthChecker health_;
  const std::chrono::milliseconds deadline_;
  const RequestScope scope_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOCATOR_CLIENT_H_
