// LocatorService: the locator.v1.Locator gRPC service (callback API) over an
// Engine that is published once the dataset has been triangulated.
//
// Owns the BatchLocator (and with it the batch worker pool). The engine is
// shared: every call copies the reference under a mutex when it starts, so
// an engine stays alive until the calls using it have finished. (Not
// std::atomic<std::shared_ptr>: libstdc++ 12's spins on a lock bit; see
// server/core/snapshot_slot.h.) Until Publish(), every RPC answers
// UNAVAILABLE "dataset is still loading".
//
// Thread-safety: all methods may be called concurrently, Publish() included.

#ifndef LOCATOR_SERVER_LOCATOR_SERVICE_H_
#define LOCATOR_SERVER_LOCATOR_SERVICE_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <memory>
#include <mutex>

#include "locator/v1/locator.grpc.pb.h"
#include "server/batch_locator.h"
#include "server/core/engine.h"

namespace locator {

struct LocatorServiceOptions {
  // Threads that locate one large batch together (see BatchLocator).
  size_t batch_threads = 1;
  // LocateBatch requests with more points fail with RESOURCE_EXHAUSTED.
  size_t max_batch_points = 1'000'000;
};

class LocatorService final : public v1::Locator::CallbackService {
 public:
  explicit LocatorService(const LocatorServiceOptions& options);

  // Starts answering with `engine`; calls already running keep the engine
  // they started with.
  void Publish(std::shared_ptr<Engine> engine);

  // The engine new calls use, or null while the dataset is loading.
  std::shared_ptr<Engine> engine() const;

  grpc::ServerUnaryReactor* Locate(grpc::CallbackServerContext* context,
                                   const v1::LocateRequest* request,
                                   v1::LocateResponse* response) override;
  grpc::ServerUnaryReactor* LocateBatch(
      grpc::CallbackServerContext* context,
      const v1::LocateBatchRequest* request,
      v1::LocateBatchResponse* response) override;
  grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>* LocateStream(
      grpc::CallbackServerContext* context) override;
  grpc::ServerUnaryReactor* GetStats(grpc::CallbackServerContext* context,
                                     const v1::GetStatsRequest* request,
                                     v1::GetStatsResponse* response) override;
  // Runs Engine::Retune on the callback thread: it is a rare operator's call
  // whose cost is bounded by the tuning budget, and the other callback
  // threads keep serving meanwhile.
  grpc::ServerUnaryReactor* Retune(grpc::CallbackServerContext* context,
                                   const v1::RetuneRequest* request,
                                   v1::RetuneResponse* response) override;

 private:
  mutable std::mutex engine_mu_;
  std::shared_ptr<Engine> engine_;  // guarded by engine_mu_
  BatchLocator batch_locator_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATOR_SERVICE_H_
