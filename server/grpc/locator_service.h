// LocatorService: the locator.v1.Locator gRPC service (callback API), a thin
// adapter over the application (LocatorApp). Each handler admits its call
// through LocatorApp::Admit (the "authorization" metadata, the drain, the
// dataset), runs the application's method, and finishes with the Status
// mapped by ToGrpcStatus (status_mapping.h), the one place where a Status
// becomes a gRPC status. Work that takes long (profiles, grids, batches,
// reloads) runs off the callback thread.
//
// Holds the application (not owned; it must outlive the service).
// Thread-safety: the handlers may be called concurrently, as gRPC does.

#ifndef LOCATOR_SERVER_GRPC_LOCATOR_SERVICE_H_
#define LOCATOR_SERVER_GRPC_LOCATOR_SERVICE_H_

#include <grpcpp/grpcpp.h>

#include "locator/v1/locator.grpc.pb.h"
#include "server/app/locator_app.h"

namespace locator {

class LocatorService final : public v1::Locator::CallbackService {
 public:
  explicit LocatorService(LocatorApp* app) : app_(app) {}

  grpc::ServerUnaryReactor* Locate(grpc::CallbackServerContext* context,
                                   const v1::LocateRequest* request,
                                   v1::LocateResponse* response) override;
  grpc::ServerUnaryReactor* LocateBatch(
      grpc::CallbackServerContext* context,
      const v1::LocateBatchRequest* request,
      v1::LocateBatchResponse* response) override;
  // Each message is routed by its own `dataset` field; the engine serving a
  // dataset when the stream first named it answers the stream's later
  // messages for it too.
  grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>* LocateStream(
      grpc::CallbackServerContext* context) override;
  grpc::ServerUnaryReactor* GetStats(grpc::CallbackServerContext* context,
                                     const v1::GetStatsRequest* request,
                                     v1::GetStatsResponse* response) override;
  // Runs on the callback thread: a rare operator's call whose cost is
  // bounded by the tuning budget; the other callback threads keep serving.
  grpc::ServerUnaryReactor* Retune(grpc::CallbackServerContext* context,
                                   const v1::RetuneRequest* request,
                                   v1::RetuneResponse* response) override;
  // Finishes when the new engine serves or the build failed (see
  // LocatorApp::Reload); the callback thread is not held meanwhile.
  grpc::ServerUnaryReactor* Reload(grpc::CallbackServerContext* context,
                                   const v1::ReloadRequest* request,
                                   v1::ReloadResponse* response) override;
  grpc::ServerUnaryReactor* GetTopology(
      grpc::CallbackServerContext* context,
      const v1::GetTopologyRequest* request,
      v1::GetTopologyResponse* response) override;
  grpc::ServerUnaryReactor* ListDatasets(
      grpc::CallbackServerContext* context,
      const v1::ListDatasetsRequest* request,
      v1::ListDatasetsResponse* response) override;
  // Traces the profile on the application's surface pool.
  grpc::ServerUnaryReactor* Profile(grpc::CallbackServerContext* context,
                                    const v1::ProfileRequest* request,
                                    v1::ProfileResponse* response) override;
  // Streams the raster, rendered in blocks on the surface pool (see
  // GridStream).
  grpc::ServerWriteReactor<v1::GridResponse>* Grid(
      grpc::CallbackServerContext* context,
      const v1::GridRequest* request) override;

 private:
  LocatorApp* const app_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_GRPC_LOCATOR_SERVICE_H_
