#include "server/locator_service.h"

#include <type_traits>
#include <utility>

#include "server/locate_stream_reactor.h"
#include "server/proto_convert.h"
#include "server/request_crs.h"
#include "server/stats_redaction.h"
#include "server/status_mapping.h"

namespace locator {
namespace {

grpc::Status LoadingStatus() {
  return grpc::Status(grpc::StatusCode::UNAVAILABLE,
                      "dataset is still loading");
}

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

// Every handler's prologue: serves the call with `serve(admission)` if
// service->Admit() lets it in, or ends it with the refusal.
template <typename Reactor, typename Serve>
Reactor* AdmitThen(LocatorService* service,
                   grpc::CallbackServerContext* context,
                   AccessPolicy::Scope scope, Serve serve) {
  LocatorService::Admission admission;
  if (grpc::Status refused = service->Admit(*context, scope, &admission);
      !refused.ok()) {
    return Refuse(context, refused, std::type_identity<Reactor>());
  }
  return serve(std::move(admission));
}

}  // namespace

LocatorService::LocatorService(const LocatorServiceOptions& options)
    : default_deadline_(options.default_deadline),
      redact_(options.access.redact),
      access_(options.access.data_token, options.access.admin_token),
      reload_policy_(options.reload_policy),
      batch_locator_(options.batch_threads, options.max_batch_points,
                     options.default_deadline),
      reloader_(
          [this, build = options.build_engine](const std::string& dataset,
                                               std::shared_ptr<Engine>* built) {
            if (!build) {
              return Status::FailedPrecondition("this server cannot reload");
            }
            const std::shared_ptr<Engine> serving = engine();
            return build(dataset, serving.get(), built);
          },
          [this](std::shared_ptr<Engine> engine) {
            return Publish(std::move(engine));
          }) {}

uint64_t LocatorService::Publish(std::shared_ptr<Engine> engine) {
  MutexLock lock(&engine_mu_);
  engine_ = std::move(engine);
  return ++generation_;
}

std::shared_ptr<Engine> LocatorService::engine() const {
  MutexLock lock(&engine_mu_);
  return engine_;
}

bool LocatorService::CurrentStats(v1::GetStatsResponse* stats) const {
  std::shared_ptr<Engine> engine;
  uint64_t generation;
  {
    MutexLock lock(&engine_mu_);
    engine = engine_;
    generation = generation_;
  }
  if (engine == nullptr) return false;
  FillStats(*engine, generation, stats);
  return true;
}

EngineStats LocatorService::OutputStats(const Engine& engine) const {
  return redact_ ? RedactStats(engine.Stats()) : engine.Stats();
}

void LocatorService::FillStats(const Engine& engine, uint64_t generation,
                               v1::GetStatsResponse* response) const {
  ToGetStatsResponse(OutputStats(engine), response);
  response->set_generation(generation);
  response->set_reload_in_progress(reloader_.in_progress());
}

Status LocatorService::StartReload(const std::string& dataset,
                                   EngineReloader::Done done) {
  return reloader_.Start(dataset, std::move(done));
}

void LocatorService::Drain(std::chrono::system_clock::time_point deadline) {
  drain_gate_.Close();
  drain_gate_.WaitUntilIdle(deadline);
}

grpc::Status LocatorService::Admit(const grpc::CallbackServerContext& context,
                                   AccessPolicy::Scope scope,
                                   Admission* admission) {
  admission->ticket = drain_gate_.Enter();
  if (admission->ticket == nullptr) {
    return ToGrpcStatus(Refusal::kShuttingDown, "server is shutting down");
  }
  if (grpc::Status denied = access_.Check(context, scope); !denied.ok()) {
    return denied;
  }
  {
    MutexLock lock(&engine_mu_);
    admission->engine = engine_;
    admission->generation = generation_;
  }
  return admission->engine != nullptr ? grpc::Status::OK : LoadingStatus();
}

grpc::ServerUnaryReactor* LocatorService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, [&](Admission call) {
        LocateResult result;
        const Status status =
            LocateInRequestCrs(*call.engine, *request, &result);
        if (status.ok()) ToLocateResponse(result, response);
        return FinishNow(context, ToGrpcStatus(status));
      });
}

grpc::ServerUnaryReactor* LocatorService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, [&](Admission call) {
        // Points in another CRS are validated first (an oversized batch
        // must not pay for a transform), then transformed once, into a copy
        // that the function holds.
        std::shared_ptr<v1::LocateBatchRequest> in_dataset_crs;
        if (!request->crs().empty()) {
          in_dataset_crs = std::make_shared<v1::LocateBatchRequest>();
          Status status = batch_locator_.Validate(*request);
          if (status.ok()) {
            status =
                BatchInDatasetCrs(*call.engine, *request, in_dataset_crs.get());
          }
          if (!status.ok()) {
            return FinishNow(context, ToGrpcStatus(status));
          }
        }
        // The function (and with it the admission) lives until the batch
        // ends.
        return batch_locator_.Serve(
            context, in_dataset_crs ? *in_dataset_crs : *request,
            [call = std::move(call), in_dataset_crs](
                std::span<const Point2> points,
                std::vector<LocateResult>* results,
                const std::function<bool()>& keep_going) {
              return call.engine->LocateBatch(points, results, keep_going);
            },
            response);
      });
}

grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>*
LocatorService::LocateStream(grpc::CallbackServerContext* context) {
  return AdmitThen<StreamReactor>(
      this, context, AccessPolicy::Scope::kData, [&](Admission call) {
        // The reactor holds the function (and with it the admission) until
        // done.
        return new LocateStreamReactor(
            context, default_deadline_,
            [call = std::move(call)](const v1::LocateRequest& request,
                                     LocateResult* result) {
              return LocateInRequestCrs(*call.engine, request, result);
            });
      });
}

grpc::ServerUnaryReactor* LocatorService::GetStats(
    grpc::CallbackServerContext* context,
    const v1::GetStatsRequest* /*request*/, v1::GetStatsResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kData, [&](Admission call) {
        FillStats(*call.engine, call.generation, response);
        return FinishNow(context, grpc::Status::OK);
      });
}

grpc::ServerUnaryReactor* LocatorService::Retune(
    grpc::CallbackServerContext* context, const v1::RetuneRequest* /*request*/,
    v1::RetuneResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      this, context, AccessPolicy::Scope::kAdmin, [&](Admission call) {
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
      this, context, AccessPolicy::Scope::kAdmin, [&](Admission call) {
        std::string dataset;
        if (grpc::Status denied =
                reload_policy_.Resolve(request->dataset(), &dataset);
            !denied.ok()) {
          return FinishNow(context, denied);
        }
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        // The reload thread finishes the call; the admission it holds until
        // then keeps a drain waiting for the build.
        const Status started = StartReload(
            dataset, [this, reactor, response, call = std::move(call)](
                         const Status& status, std::shared_ptr<Engine> engine,
                         uint64_t generation) {
              if (status.ok()) {
                ToReloadResponse(OutputStats(*engine), generation, response);
              }
              reactor->Finish(ToGrpcStatus(status));
            });
        if (!started.ok()) reactor->Finish(ToGrpcStatus(started));
        return reactor;
      });
}

}  // namespace locator
