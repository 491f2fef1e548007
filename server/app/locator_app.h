// LocatorApp: the locator application, whatever transport brings the calls.
// It serves the server's named datasets (DatasetRegistry), each by an Engine
// that is published once its dataset has been triangulated, and answers the
// locator.v1 requests (the proto messages are its typed requests and
// answers) with a Status. It knows neither gRPC nor HTTP: the gRPC service
// (server/grpc/locator_service.h) and the HTTP/JSON API
// (server/http/json/json_api.h) are thin adapters over it, and each maps a
// Status to its transport in one place.
//
// Owns the DatasetRegistry, the BatchLocator (and with it the batch worker
// pool), the surface pool and the AccessPolicy. Engines are shared: a call
// copies its dataset's engine reference when it is admitted, so an engine
// stays alive until the calls using it have finished.
//
// Every output of an engine's statistics (GetStats, Retune, Reload,
// ListDatasets, CurrentStats(): /api/stats, /metrics, logs) is made from
// OutputStats(), which applies --redact once.
//
// Every call is admitted by Admit(), which refuses, in this order: calls
// started after Drain() began (UNAVAILABLE "server is shutting down"; see
// DrainGate), calls the AccessPolicy does not allow (UNAUTHENTICATED /
// PERMISSION_DENIED), calls naming an unknown dataset (NOT_FOUND listing the
// known names), and calls to a dataset whose first engine is still being
// built (UNAVAILABLE "dataset 'NAME' is still loading"). The dataset is
// resolved there once per call; a LocateStream names none at its start, and
// each of its messages is resolved by its adapter with Resolve().
//
// Thread-safety: all methods may be called concurrently.

#ifndef LOCATOR_SERVER_APP_LOCATOR_APP_H_
#define LOCATOR_SERVER_APP_LOCATOR_APP_H_

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "locator/engine.h"
#include "locator/raster.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"
#include "server/app/batch_locator.h"
#include "server/config/dataset_flag.h"
#include "server/config/security_config.h"
#include "server/datasets/dataset_registry.h"
#include "server/serving/access_policy.h"
#include "server/serving/call_deadline.h"
#include "server/serving/drain_gate.h"
#include "server/serving/worker_pool.h"

namespace locator {

struct LocatorAppOptions {
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
  // The deadline of a call whose client set none (zero: none).
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

class LocatorApp {
 public:
  explicit LocatorApp(const LocatorAppOptions& options);

  LocatorApp(const LocatorApp&) = delete;
  LocatorApp& operator=(const LocatorApp&) = delete;

  // Who may call what (the tokens), for what else the server answers.
  const AccessPolicy& access_policy() const { return access_; }

  // The datasets served.
  DatasetRegistry& datasets() { return registry_; }
  const DatasetRegistry& datasets() const { return registry_; }

  // Profiles and grid blocks run here, off the transports' threads.
  WorkerPool& surface_pool() { return surface_pool_; }

  // The deadline of a call whose client set none: the server's default from
  // now (none when it is zero).
  CallDeadline DefaultDeadline() const {
    return CallDeadline::ServerDefault(default_deadline_);
  }
  // The server's default deadline (zero: none).
  std::chrono::milliseconds default_deadline() const {
    return default_deadline_;
  }

  // GetStats for `dataset` ("": the default) as answered now (redacted with
  // --redact). NotFound for an unknown dataset, Unavailable while it loads.
  StatusOr<v1::GetStatsResponse> CurrentStats(std::string_view dataset) const;
  // The engine serving `dataset` now, with CurrentStats()'s errors.
  StatusOr<std::shared_ptr<Engine>> ServingEngine(
      std::string_view dataset) const;

  // Refuses new calls from now on (UNAVAILABLE) and waits until the calls
  // already admitted have ended or `deadline` passes. Called when the server
  // starts draining, before the transports shut down.
  void Drain(std::chrono::system_clock::time_point deadline);

  // What an admitted call runs with. Whatever finishes the call holds it:
  // the ticket keeps the call counted as in flight.
  struct Admission {
    // The dataset the call is for and the engine serving it then; null for
    // calls that name none (ListDatasets, LocateStream).
    DatasetSlot* dataset = nullptr;
    std::shared_ptr<Engine> engine;
    // The tiles `engine` serves, for a tile set; null otherwise.
    std::shared_ptr<const ShardTiles> tiles;
    uint64_t generation = 0;  // of `engine`
    DrainGate::Ticket ticket;
  };

  // The admission of a call presenting `authorization` (the
  // "authorization" metadata or header value; nullopt without one) for a
  // request of `scope` on `dataset` ("": the default; nullopt: a call about
  // no single dataset), or the refusal to finish it with (see above).
  StatusOr<Admission> Admit(std::optional<std::string_view> authorization,
                            AccessPolicy::Scope scope,
                            std::optional<std::string_view> dataset);
  // The dataset `name` ("": the default) and the engine serving it now, for
  // a call already admitted: NotFound for an unknown one, Unavailable while
  // it loads.
  StatusOr<Admission> Resolve(std::string_view name) const;

  // Locate on an admitted call.
  Status Locate(const Admission& call, const v1::LocateRequest& request,
                v1::LocateResponse* response) const;
  // Locates `request` on the dataset `call` resolved (a LocateStream's
  // message, resolved by the stream with Resolve()). FailedPrecondition for
  // a point of a tile this server does not serve (ShardTiles).
  Status LocateOn(const Admission& call, const v1::LocateRequest& request,
                  LocateResult* result) const;
  // Whose batch LocateBatch answers.
  enum class BatchFor {
    // locator.v1's: a point outside the area of use of the request's CRS
    // fails the call (INVALID_ARGUMENT naming the point), and so does a
    // point of a tile this server does not serve (FAILED_PRECONDITION: a
    // stale route).
    kLocate,
    // The elevation APIs' (Open Topo Data, OGC API EDR): a point outside
    // the area of use is answered OUTSIDE_CONVEX_HULL without a value (they
    // answer null there), and points of every tile are answered
    // (LocateBatchWhereDefined).
    kElevation,
  };
  // LocateBatch on an admitted call, finished through control.finish (see
  // BatchLocator::Run); `request` and `response` must live until then.
  void LocateBatch(Admission call, const v1::LocateBatchRequest& request,
                   BatchLocator::CallControl control,
                   v1::LocateBatchResponse* response,
                   BatchFor batch_for = BatchFor::kLocate);
  // GetTopology on an admitted call: the tiles of a tile set and those this
  // server serves, or one shard (this server) for any other dataset.
  void GetTopology(const Admission& call,
                   v1::GetTopologyResponse* response) const;
  // ListDatasets.
  void ListDatasets(v1::ListDatasetsResponse* response) const;
  // GetStats on an admitted call.
  void GetStats(const Admission& call, v1::GetStatsResponse* response) const;
  // Retune on an admitted call; runs on the calling thread (a rare
  // operator's call whose cost is bounded by the tuning budget).
  void Retune(const Admission& call, v1::RetuneResponse* response) const;
  // Loads into the admitted call's dataset what `request` asks for and its
  // reload policy allows (PERMISSION_DENIED otherwise), on the dataset's
  // reload thread; `done` gets the outcome there once the new engine serves
  // or the build failed, or at once for a refused request. `response` must
  // live until then. The other datasets are not touched.
  void Reload(Admission call, const v1::ReloadRequest& request,
              v1::ReloadResponse* response,
              std::function<void(const Status&)> done);
  // Profile on an admitted call (run it on surface_pool()).
  Status Profile(const Admission& call, const v1::ProfileRequest& request,
                 v1::ProfileResponse* response) const;
  // The raster a Grid `request` on an admitted call asks for, checked
  // against the cell limit and the dataset's interpolation.
  StatusOr<RasterSpec> GridSpec(const Admission& call,
                                const v1::GridRequest& request) const;

 private:
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
  // max(1, batch_threads) threads.
  WorkerPool surface_pool_;
  DatasetRegistry registry_;  // last: its reload threads use the rest
};

}  // namespace locator

#endif  // LOCATOR_SERVER_APP_LOCATOR_APP_H_
