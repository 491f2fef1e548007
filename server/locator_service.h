// LocatorService: the locator.v1.Locator gRPC service (callback API) over an
// Engine that is published once the dataset has been triangulated.
//
// Owns the BatchLocator (and with it the batch worker pool) and the
// AccessPolicy. The engine is shared: every call copies the reference under
// a mutex when it starts, so an engine stays alive until the calls using it
// have finished. (Not std::atomic<std::shared_ptr>: libstdc++ 12's spins on
// a lock bit; see server/core/snapshot_slot.h.)
//
// Every output of the engine's statistics, here (GetStats, Retune, Reload)
// and elsewhere (CurrentStats(): /api/stats, /metrics, logs), is made from
// OutputStats(), which applies --redact once.
//
// Every handler starts with Admit(), which refuses, in this order: calls
// started after Drain() began (UNAVAILABLE "server is shutting down"; see
// DrainGate), calls the AccessPolicy does not allow (UNAUTHENTICATED /
// PERMISSION_DENIED), and, until Publish(), every call (UNAVAILABLE "dataset
// is still loading").
//
// Thread-safety: all methods may be called concurrently, Publish() included.

#ifndef LOCATOR_SERVER_LOCATOR_SERVICE_H_
#define LOCATOR_SERVER_LOCATOR_SERVICE_H_

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "common/mutex.h"
#include "common/status.h"
#include "locator/v1/locator.grpc.pb.h"
#include "server/access_policy.h"
#include "server/batch_locator.h"
#include "server/core/engine.h"
#include "server/drain_gate.h"
#include "server/engine_reloader.h"
#include "server/reload_policy.h"
#include "server/security_config.h"

namespace locator {

struct LocatorServiceOptions {
  // Threads that locate one large batch together (see BatchLocator).
  size_t batch_threads = 1;
  // LocateBatch requests with more points fail with RESOURCE_EXHAUSTED.
  size_t max_batch_points = 1'000'000;
  // The deadline of a LocateBatch or LocateStream whose client set none
  // (zero: none).
  std::chrono::milliseconds default_deadline{0};
  // Tokens and redaction.
  AccessConfig access;
  // Which datasets a Reload RPC may load (the default: only the configured
  // one).
  ReloadPolicy reload_policy;
  // Builds the engine for a dataset spec ("": the configured dataset), given
  // the engine serving now (null before the first); runs on the reload
  // thread. Unset: reloads fail with FAILED_PRECONDITION.
  std::function<Status(const std::string& dataset, Engine* serving,
                       std::shared_ptr<Engine>* built)>
      build_engine;
};

class LocatorService final : public v1::Locator::CallbackService {
 public:
  explicit LocatorService(const LocatorServiceOptions& options);

  // Starts answering with `engine`; calls already running keep the engine
  // they started with. Returns its generation.
  uint64_t Publish(std::shared_ptr<Engine> engine) EXCLUDES(engine_mu_);

  // The engine new calls use, or null while the dataset is loading.
  std::shared_ptr<Engine> engine() const EXCLUDES(engine_mu_);

  // Fills `stats` as GetStats would answer now (redacted with --redact);
  // false, and nothing filled, while the dataset is loading.
  bool CurrentStats(v1::GetStatsResponse* stats) const EXCLUDES(engine_mu_);

  // Builds an engine for `dataset` ("": the configured one) with
  // options.build_engine on the reload thread and publishes it; then calls
  // `done` there with the outcome (see EngineReloader::Start).
  // FailedPrecondition "reload in progress" while another build runs.
  Status StartReload(const std::string& dataset, EngineReloader::Done done);

  // Refuses new calls from now on (UNAVAILABLE) and waits until the calls
  // already admitted have ended or `deadline` passes. Called when the server
  // starts draining, before gRPC's shutdown.
  void Drain(std::chrono::system_clock::time_point deadline);

  // What an admitted call runs with. Whatever finishes the call holds it:
  // the ticket keeps the call counted as in flight.
  struct Admission {
    std::shared_ptr<Engine> engine;
    uint64_t generation = 0;  // of `engine`
    DrainGate::Ticket ticket;
  };

  // OK if a call with `context` may run an RPC of `scope` now, with
  // `*admission` set; otherwise the refusal to finish it with (see above).
  grpc::Status Admit(const grpc::CallbackServerContext& context,
                     AccessPolicy::Scope scope, Admission* admission);

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
  // Loads what options.reload_policy allows (PERMISSION_DENIED otherwise).
  // Finishes when the new engine serves or the build failed (see
  // StartReload); the callback thread is not held meanwhile.
  grpc::ServerUnaryReactor* Reload(grpc::CallbackServerContext* context,
                                   const v1::ReloadRequest* request,
                                   v1::ReloadResponse* response) override;

 private:
  // `engine`'s statistics as every output shows them: redacted with
  // --redact.
  EngineStats OutputStats(const Engine& engine) const;
  // Fills `response` for `engine` serving as `generation`.
  void FillStats(const Engine& engine, uint64_t generation,
                 v1::GetStatsResponse* response) const;

  const std::chrono::milliseconds default_deadline_;
  const bool redact_;
  const AccessPolicy access_;
  const ReloadPolicy reload_policy_;
  DrainGate drain_gate_;
  mutable Mutex engine_mu_;
  std::shared_ptr<Engine> engine_ GUARDED_BY(engine_mu_);
  uint64_t generation_ GUARDED_BY(engine_mu_) = 0;
  BatchLocator batch_locator_;
  EngineReloader reloader_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATOR_SERVICE_H_
