// LocatorService: the locator.v1.Locator gRPC service (callback API) over
// the server's named datasets (DatasetRegistry), each served by an Engine
// that is published once its dataset has been triangulated.
//
// Owns the DatasetRegistry, the BatchLocator (and with it the batch worker
// pool) and the AccessPolicy. Engines are shared: a call copies its
// dataset's engine reference when it is admitted, so an engine stays alive
// until the calls using it have finished.
//
// Every output of an engine's statistics, here (GetStats, Retune, Reload,
// ListDatasets) and elsewhere (CurrentStats(): /api/stats, /metrics, logs),
// is made from OutputStats(), which applies --redact once.
//
// Every call, gRPC or HTTP, is admitted by Admit(), which refuses, in this
// order: calls started after Drain() began (UNAVAILABLE "server is shutting
// down"; see DrainGate), calls the AccessPolicy does not allow
// (UNAUTHENTICATED / PERMISSION_DENIED), calls naming an unknown dataset
// (NOT_FOUND listing the known names), and calls to a dataset whose first
// engine is still being built (UNAVAILABLE "dataset 'NAME' is still
// loading"). The dataset is resolved there once per call; a LocateStream
// names none at its start, and each of its messages is routed by its own
// `dataset` field (the engine serving that dataset when the stream first
// named it answers the stream's later messages for it too).
//
// The work of each RPC, after admission, is one Run*() method that the
// gRPC handlers and the HTTP/JSON API (server/http/json/json_api.h) both call.
//
// Thread-safety: all methods may be called concurrently.

#ifndef LOCATOR_SERVER_LOCATOR_SERVICE_H_
#define LOCATOR_SERVER_LOCATOR_SERVICE_H_

#include <grpcpp/grpcpp.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "locator/engine.h"
#include "locator/raster.h"
#include "locator/status.h"
#include "locator/v1/locator.grpc.pb.h"
#include "server/config/dataset_flag.h"
#include "server/config/security_config.h"
#include "server/datasets/dataset_registry.h"
#include "server/serving/access_policy.h"
#include "server/serving/batch_locator.h"
#include "server/serving/drain_gate.h"
#include "server/serving/worker_pool.h"

namespace locator {

struct LocatorServiceOptions {
  // Threads that locate one large batch together (see BatchLocator).
  size_t batch_threads = 1;
  // LocateBatch requests with more points fail with RESOURCE_EXHAUSTED.
  size_t max_batch_points = 1'000'000;
  // A Profile whose line crosses more triangle edges (in holes too) fails
  // with RESOURCE_EXHAUSTED.
  uint64_t max_profile_crossings = 1'000'000;
  // A Profile asking for more samples fails with RESOURCE_EXHAUSTED.
  uint32_t max_profile_samples = 100'000;
  // A Grid of more cells fails with RESOURCE_EXHAUSTED.
  uint64_t max_grid_cells = uint64_t{1} << 24;
  // The deadline of a LocateBatch or LocateStream whose client set none
  // (zero: none).
  std::chrono::milliseconds default_deadline{0};
  // Tokens and redaction.
  AccessConfig access;
  // The datasets, in flag order; the first is the default. By default one,
  // "default", whose configured spec is "".
  std::vector<DatasetConfig> datasets = {DatasetConfig()};
  // --reload-dir: what a Reload may load besides a dataset's own spec (see
  // ReloadPolicy); empty: only that.
  std::string reload_dir;
  // Builds a dataset's engines, at start and on reloads. Unset: reloads
  // fail with FAILED_PRECONDITION.
  DatasetBuild build_engine;
};

class LocatorService final : public v1::Locator::CallbackService {
 public:
  explicit LocatorService(const LocatorServiceOptions& options);

  // Who may call what (the tokens), for what else the server answers.
  const AccessPolicy& access_policy() const { return access_; }

  // The datasets served.
  DatasetRegistry& datasets() { return registry_; }
  const DatasetRegistry& datasets() const { return registry_; }

  // Fills `stats` as GetStats for `dataset` ("": the default) would answer
  // now (redacted with --redact). NotFound for an unknown dataset,
  // Unavailable while it is loading (nothing filled then).
  Status CurrentStats(std::string_view dataset,
                      v1::GetStatsResponse* stats) const;
  // Sets `engine` to the engine serving `dataset` now, with
  // CurrentStats()'s errors.
  Status ServingEngine(std::string_view dataset,
                       std::shared_ptr<Engine>* engine) const;

  // Refuses new calls from now on (UNAVAILABLE) and waits until the calls
  // already admitted have ended or `deadline` passes. Called when the server
  // starts draining, before gRPC's shutdown.
  void Drain(std::chrono::system_clock::time_point deadline);

  // What an admitted call runs with. Whatever finishes the call holds it:
  // the ticket keeps the call counted as in flight.
  struct Admission {
    // The dataset the call is for and the engine serving it then; null for
    // calls that name none (ListDatasets, LocateStream).
    DatasetSlot* dataset = nullptr;
    std::shared_ptr<Engine> engine;
    uint64_t generation = 0;  // of `engine`
    DrainGate::Ticket ticket;
  };

  // OK if a call presenting `authorization` (the "authorization" metadata or
  // header value; nullopt without one) may run an RPC of `scope` on
  // `dataset` ("": the default; nullopt: a call about no single dataset)
  // now, with `*admission` set; otherwise the refusal to finish it with
  // (see above).
  grpc::Status Admit(std::optional<std::string_view> authorization,
                     AccessPolicy::Scope scope,
                     std::optional<std::string_view> dataset,
                     Admission* admission);
  // The same for the gRPC call of `context`.
  grpc::Status Admit(const grpc::CallbackServerContext& context,
                     AccessPolicy::Scope scope,
                     std::optional<std::string_view> dataset,
                     Admission* admission);

  // The work of Locate on an admitted call.
  grpc::Status RunLocate(const Admission& call,
                         const v1::LocateRequest& request,
                         v1::LocateResponse* response) const;
  // The work of LocateBatch on an admitted call, finished through
  // control.finish (see BatchLocator::Run); `request` and `response` must
  // live until then.
  void RunLocateBatch(Admission call, const v1::LocateBatchRequest& request,
                      BatchLocator::CallControl control,
                      v1::LocateBatchResponse* response);
  // The work of ListDatasets.
  void RunListDatasets(v1::ListDatasetsResponse* response) const;
  // The work of Profile on an admitted call.
  grpc::Status RunProfile(const Admission& call,
                          const v1::ProfileRequest& request,
                          v1::ProfileResponse* response) const;
  // The raster a Grid `request` on an admitted call asks for, checked
  // against the cell limit and the dataset's interpolation.
  grpc::Status GridSpec(const Admission& call, const v1::GridRequest& request,
                        RasterSpec* spec) const;
  // The deadline a call without one is held to (see BatchLocator).
  CallDeadline DefaultDeadline() const {
    return batch_locator_.DefaultDeadline();
  }

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
  // Loads into the dataset request.name names what its reload policy
  // allows (PERMISSION_DENIED otherwise). Finishes when the new engine
  // serves or the build failed (see DatasetSlot::StartReload); the callback
  // thread is not held meanwhile. The other datasets are not touched.
  grpc::ServerUnaryReactor* Reload(grpc::CallbackServerContext* context,
                                   const v1::ReloadRequest* request,
                                   v1::ReloadResponse* response) override;
  grpc::ServerUnaryReactor* ListDatasets(
      grpc::CallbackServerContext* context,
      const v1::ListDatasetsRequest* request,
      v1::ListDatasetsResponse* response) override;
  // Traces the profile on the surface pool, off the callback thread.
  grpc::ServerUnaryReactor* Profile(grpc::CallbackServerContext* context,
                                    const v1::ProfileRequest* request,
                                    v1::ProfileResponse* response) override;
  // Streams the raster, rendered in blocks on the surface pool (see
  // GridStream).
  grpc::ServerWriteReactor<v1::GridResponse>* Grid(
      grpc::CallbackServerContext* context,
      const v1::GridRequest* request) override;

 private:
  // Sets admission's dataset, engine and generation for `name` ("": the
  // default): NotFound for an unknown one, Unavailable while it loads.
  Status Resolve(std::string_view name, Admission* admission) const;
  // `engine`'s statistics as every output shows them: redacted with
  // --redact.
  EngineStats OutputStats(const Engine& engine) const;
  // Fills `response` for `engine` serving `dataset` as `generation`.
  void FillStats(const DatasetSlot& dataset, const Engine& engine,
                 uint64_t generation, v1::GetStatsResponse* response) const;

  const std::chrono::milliseconds default_deadline_;
  const uint64_t max_profile_crossings_;
  const uint32_t max_profile_samples_;
  const uint64_t max_grid_cells_;
  const bool redact_;
  const AccessPolicy access_;
  DrainGate drain_gate_;
  BatchLocator batch_locator_;
  // Profiles and grid blocks run here: max(1, batch_threads) threads.
  WorkerPool surface_pool_;
  DatasetRegistry registry_;  // last: its reload threads use the rest
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATOR_SERVICE_H_
