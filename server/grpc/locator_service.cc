#include "server/grpc/locator_service.h"

#include <algorithm>
#include <map>
#include <type_traits>
#include <utility>

#include "server/grpc/grid_stream.h"
#include "server/grpc/locate_stream_reactor.h"
#include "server/grpc/proto_convert.h"
#include "server/grpc/status_mapping.h"
#include "server/grpc/surface_convert.h"
#include "server/serving/request_crs.h"
#include "server/serving/stats_redaction.h"

namespace locator {
namespace {

using StreamReactor =
    grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>;

// Ends a stream at once, before reading anything.
class RejectedStreamReactor final : public StreamReactor {
 public:
  explicit RejectedStreamReactor(const grpc::Status& status) { Finish(status); }
  void OnDone() override { delete this; }
};

grpc::ServerUnaryReactor* FinishNow(grpc::CallbackServerContext* context,
                                    const grpc::Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(status);
  return reactor;
}

// The reactor that ends a refused call at once, per kind of call.
grpc::ServerUnaryReactor* Refuse(grpc::CallbackServerContext* context,
                                 const grpc::Status& status,
                                 std::type_identity<grpc::ServerUnaryReactor>) {
  return FinishNow(context, status);
}
StreamReactor* Refuse(grpc::CallbackServerContext* /*context*/,
                      const grpc::Status& status,
                      std::type_identity<StreamReactor>) {
  return new RejectedStreamReactor(status);
}

// Ends a Grid stream at once, before writing anything.
class RejectedGridReactor final
    : public grpc::ServerWriteReactor<v1::GridResponse> {
 public:
  explicit RejectedGridReactor(const grpc::Status& status) { Finish(status); }
  void OnDone() override { delete this; }
};

grpc::ServerWriteReactor<v1::GridResponse>* Refuse(
    grpc::CallbackServerContext* /*context*/, const grpc::Status& status,
    std::type_identity<grpc::ServerWriteReactor<v1::GridResponse>>) {
  return new RejectedGridReactor(status);
}

// Every handler's prologue: serves the call with `serve(admission)` if
// service->Admit() lets it in for `dataset` (nullopt: no single dataset),
// or ends it with the refusal.
template <typename Reactor, typename Serve>
Reactor* AdmitThen(LocatorService* service,
                   grpc::CallbackServerContext* context,
                   AccessPolicy::Scope scope,
                   std::optional<std::string_view> dataset, Serve serve) {
  LocatorService::Admission admission;
  if (grpc::Status refused =
          service->Admit(*context, scope, dataset, &admission);
      !refused.ok()) {
    return Refuse(context, refused, std::type_identity<Reactor>());
  }
  return serve(std::move(admission));
}

// The message of a failed Reload of `dataset` that asked for `requested`
// (resolved to `spec`; both "" for the configured spec), as a client sees it
// with --redact: it names the file as the client did (the configured one as
// "dataset 'NAME'") and no server path (see RedactPaths), and keeps the
// line and the reason.
std::string RedactedReloadError(const DatasetSlot& dataset,
                                const std::string& requested,
                                const std::string& spec, const Status& status) {
  // The loader names what it loaded: the resolved spec, or the configured
  // one when the request named none.
  const std::string configured_as =
      requested.empty() ? "dataset '" + dataset.name() + "'" : requested;
  return RedactPaths(status.message(),
                     {{.path = spec, .shown = requested},
                      {.path = dataset.spec(), .shown = configured_as}});
}

}  // namespace

LocatorService::LocatorService(const LocatorServiceOptions& options)
    : default_deadline_(options.default_deadline),
      max_profile_crossings_(options.max_profile_crossings),
      max_profile_samples_(options.max_profile_samples),
      max_grid_cells_(options.max_grid_cells),
      redact_(options.access.redact),
      access_(options.access.data_token, options.access.admin_token),
      batch_locator_(options.batch_threads, options.max_batch_points,
                     options.default_deadline),
      surface_pool_(std::max<size_t>(1, options.batch_threads)),
      registry_(options.datasets, options.reload_dir, options.build_engine) {}

Status LocatorService::Resolve(std::string_view name,
                               Admission* admission) const {
  DatasetSlot* slot = nullptr;
  if (Status status = registry_.Find(name, &slot); !status.ok()) {
    return status;
  }
  DatasetSlot::Serving serving = slot->serving();
  if (serving.engine == nullptr) {
    return Status::Unavailable("dataset '" + slot->name() +
                               "' is still loading");
  }
  admission->dataset = slot;
  admission->engine = std::move(serving.engine);
  admission->generation = serving.generation;
  return Status::OK();
}

Status LocatorService::CurrentStats(std::string_view dataset,
                                    v1::GetStatsResponse* stats) const {
  Admission current;
  if (Status status = Resolve(dataset, &current); !status.ok()) return status;
  FillStats(*current.dataset, *current.engine, current.generation, stats);
  return Status::OK();
}

Status LocatorService::ServingEngine(std::string_view dataset,
                                     std::shared_ptr<Engine>* engine) const {
  Admission current;
  if (Status status = Resolve(dataset, &current); !status.ok()) return status;
  *engine = std::move(current.engine);
  return Status::OK();
}

EngineStats LocatorService::OutputStats(const Engine& engine) const {
  return redact_ ? RedactStats(engine.Stats()) : engine.Stats();
}

void LocatorService::FillStats(const DatasetSlot& dataset, const Engine& engine,
                               uint64_t generation,
                               v1::GetStatsResponse* response) const {
  ToGetStatsResponse(OutputStats(engine), response);
  response->mutable_dataset()->set_name(dataset.name());
  response->set_generation(generation);
  response->set_reload_in_progress(dataset.reload_in_progress());
}

void LocatorService::Drain(std::chrono::system_clock::time_point deadline) {
  drain_gate_.Close();
  drain_gate_.WaitUntilIdle(deadline);
}

grpc::Status LocatorService::Admit(
    std::optional<std::string_view> authorization, AccessPolicy::Scope scope,
    std::optional<std::string_view> dataset, Admission* admission) {
  admission->ticket = drain_gate_.Enter();
  if (admission->ticket == nullptr) {
    return ToGrpcStatus(Refusal::kShuttingDown, "server is shutting down");
  }
  if (grpc::Status denied = access_.CheckAuthorization(authorization, scope);
      !denied.ok()) {
    return denied;
  }
  if (!dataset.has_value()) return grpc::Status::OK;
  return ToGrpcStatus(Resolve(*dataset, admission));
}

grpc::Status LocatorService::Admit(const grpc::CallbackServerContext& context,
                                   AccessPolicy::Scope scope,
                                   std::optional<std::string_view> dataset,
                                   Admission* admission) {
  return Admit(AccessPolicy::Authorization(context), scope, dataset, admission);
}

grpc::Status LocatorService::RunLocate(const Admission& call,
                                       const v1::LocateRequest& request,
                                       v1::LocateResponse* response) const {
  LocateResult result;
  const Status status = LocateInRequestCrs(*call.engine, request, &result);
  if (status.ok()) ToLocateResponse(result, response);
  return ToGrpcStatus(status);
}

void LocatorService::RunLocateBatch(Admission call,
                                    const v1::LocateBatchRequest& request,
                                    BatchLocator::CallControl control,
                                    v1::LocateBatchResponse* response) {
  Interpolation how;
  if (Status status = FromInterpolation(request.interpolation(), &how);
      !status.ok()) {
    control.finish(ToGrpcStatus(status));
    return;
  }
  // Points in another CRS are validated first (an oversized batch must not
  // pay for a transform), then transformed once, into a copy that the
  // function holds.
  std::shared_ptr<v1::LocateBatchRequest> in_dataset_crs;
  if (!request.crs().empty()) {
    in_dataset_crs = std::make_shared<v1::LocateBatchRequest>();
    Status status = batch_locator_.Validate(request);
    if (status.ok()) {
      status = BatchInDatasetCrs(*call.engine, request, in_dataset_crs.get());
    }
    if (!status.ok()) {
      control.finish(ToGrpcStatus(status));
      return;
    }
  }
  // Barycentrics and values are computed only when asked for.
  const Detail detail =
      request.include_barycentric() || request.include_values()
          ? Detail::kFull
          : Detail::kLocation;
  // The function (and with it the admission) lives until the batch ends.
  batch_locator_.Run(
      in_dataset_crs ? *in_dataset_crs : request,
      [call = std::move(call), in_dataset_crs, how, detail](
          std::span<const Point2> points, std::vector<LocateResult>* results,
          const std::function<bool()>& keep_going) {
        return call.engine->LocateBatch(points, results, keep_going, how,
                                        detail);
      },
      std::move(control), response);
}

void LocatorService::RunListDatasets(v1::ListDatasetsResponse* response) const {
  for (const std::unique_ptr<DatasetSlot>& slot : registry_.slots()) {
    v1::DatasetEntry* entry = response->add_datasets();
    const DatasetSlot::Serving serving = slot->serving();
    if (serving.engine != nullptr) {
      ToDatasetEntry(OutputStats(*serving.engine), serving.generation, entry);
      entry->mutable_stats()->set_name(slot->name());
    }
    entry->set_name(slot->name());
    entry->set_is_default(slot->is_default());
    entry->set_serving(serving.engine != nullptr);
  }
}

grpc::ServerUnaryReactor* LocatorService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        return FinishNow(context, RunLocate(call, *request, response));
      });
}

grpc::ServerUnaryReactor* LocatorService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        RunLocateBatch(std::move(call), *request,
                       batch_locator_.ControlFor(context, reactor), response);
        return reactor;
      });
}

grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>*
LocatorService::LocateStream(grpc::CallbackServerContext* context) {
  return AdmitThen<StreamReactor>(
      this, context, AccessPolicy::Scope::kData, std::nullopt,
      [&](Admission call) {
        // The reactor holds the function (and with it the admission and the
        // engines the stream resolved) until done. Its reactions run one at
        // a time, so `resolved` needs no lock of its own.
        return new LocateStreamReactor(
            context, default_deadline_,
            [this, call = std::move(call),
             resolved = std::map<const DatasetSlot*, Admission>()](
                const v1::LocateRequest& request,
                LocateResult* result) mutable {
              Admission dataset;
              if (Status status = Resolve(request.dataset(), &dataset);
                  !status.ok()) {
                return status;
              }
              const Admission& pinned =
                  resolved.try_emplace(dataset.dataset, std::move(dataset))
                      .first->second;
              return LocateInRequestCrs(*pinned.engine, request, result);
            });
      });
}

grpc::ServerUnaryReactor* LocatorService::GetStats(
    grpc::CallbackServerContext* context, const v1::GetStatsRequest* request,
    v1::GetStatsResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        FillStats(*call.dataset, *call.engine, call.generation, response);
        return FinishNow(context, grpc::Status::OK);
      });
}

grpc::ServerUnaryReactor* LocatorService::Retune(
    grpc::CallbackServerContext* context, const v1::RetuneRequest* request,
    v1::RetuneResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kAdmin, request->dataset(),
      [&](Admission call) {
        call.engine->Retune();
        ToTuningStats(OutputStats(*call.engine).tuning,
                      /*include_histogram=*/false, response->mutable_tuning());
        return FinishNow(context, grpc::Status::OK);
      });
}

grpc::ServerUnaryReactor* LocatorService::Reload(
    grpc::CallbackServerContext* context, const v1::ReloadRequest* request,
    v1::ReloadResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kAdmin, request->name(),
      [&](Admission call) {
        DatasetSlot* dataset = call.dataset;
        std::string requested;
        if (Status bad = FromReloadRequest(*request, &requested); !bad.ok()) {
          return FinishNow(context, ToGrpcStatus(bad));
        }
        std::string spec;
        if (grpc::Status denied =
                dataset->reload_policy().Resolve(requested, &spec);
            !denied.ok()) {
          return FinishNow(context, denied);
        }
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        // The reload thread finishes the call; the admission it holds until
        // then keeps a drain waiting for the build.
        const Status started = dataset->StartReload(
            spec,
            [this, reactor, response, requested, spec, call = std::move(call)](
                const Status& status, std::shared_ptr<Engine> engine,
                uint64_t generation) {
              if (status.ok()) {
                ToReloadResponse(OutputStats(*engine), generation, response);
                response->mutable_dataset()->set_name(call.dataset->name());
              }
              reactor->Finish(
                  redact_ ? ToGrpcStatus(status, RedactedReloadError(
                                                     *call.dataset, requested,
                                                     spec, status))
                          : ToGrpcStatus(status));
            });
        if (!started.ok()) reactor->Finish(ToGrpcStatus(started));
        return reactor;
      });
}

grpc::ServerUnaryReactor* LocatorService::ListDatasets(
    grpc::CallbackServerContext* context,
    const v1::ListDatasetsRequest* /*request*/,
    v1::ListDatasetsResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, std::nullopt,
      [&](Admission /*call*/) {
        RunListDatasets(response);
        return FinishNow(context, grpc::Status::OK);
      });
}

grpc::ServerUnaryReactor* LocatorService::Profile(
    grpc::CallbackServerContext* context, const v1::ProfileRequest* request,
    v1::ProfileResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        surface_pool_.Submit(
            [this, reactor, request, response, call = std::move(call)] {
              reactor->Finish(RunProfile(call, *request, response));
            });
        return reactor;
      });
}

grpc::ServerWriteReactor<v1::GridResponse>* LocatorService::Grid(
    grpc::CallbackServerContext* context, const v1::GridRequest* request) {
  using GridReactor = grpc::ServerWriteReactor<v1::GridResponse>;
  return AdmitThen<GridReactor>(
      this, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) -> GridReactor* {
        RasterSpec spec;
        if (grpc::Status refused = GridSpec(call, *request, &spec);
            !refused.ok()) {
          return new RejectedGridReactor(refused);
        }
        std::shared_ptr<const Engine> engine = call.engine;
        const std::string crs = engine->dataset_info().crs;
        return new GridStream(context,
                              CallDeadline::For(*context, default_deadline_),
                              std::move(engine), spec, crs, &surface_pool_,
                              std::make_shared<Admission>(std::move(call)));
      });
}

}  // namespace locator
