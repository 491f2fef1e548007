#include "server/grpc/locator_service.h"

#include <map>
#include <type_traits>
#include <utility>

#include "common/status_mapping.h"
#include "server/grpc/call_context.h"
#include "server/grpc/grid_stream.h"
#include "server/grpc/locate_stream_reactor.h"

namespace locator {
namespace {

using Admission = LocatorApp::Admission;
using StreamReactor =
    grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>;
using GridReactor = grpc::ServerWriteReactor<v1::GridResponse>;

grpc::ServerUnaryReactor* FinishNow(grpc::CallbackServerContext* context,
                                    const Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(ToGrpcStatus(status));
  return reactor;
}

// Ends a stream at once, before reading or writing anything.
template <typename Reactor>
class RejectedReactor final : public Reactor {
 public:
  explicit RejectedReactor(const Status& status) {
    this->Finish(ToGrpcStatus(status));
  }
  void OnDone() override { delete this; }
};

// The reactor that ends a refused call at once, per kind of call.
grpc::ServerUnaryReactor* Refuse(grpc::CallbackServerContext* context,
                                 const Status& status,
                                 std::type_identity<grpc::ServerUnaryReactor>) {
  return FinishNow(context, status);
}
template <typename Reactor>
Reactor* Refuse(grpc::CallbackServerContext* /*context*/, const Status& status,
                std::type_identity<Reactor>) {
  return new RejectedReactor<Reactor>(status);
}

// Every handler's prologue: serves the call with `serve(admission)` if the
// application admits it for `dataset` (nullopt: no single dataset), or ends
// it with the refusal.
template <typename Reactor, typename Serve>
Reactor* AdmitThen(LocatorApp* app, grpc::CallbackServerContext* context,
                   AccessPolicy::Scope scope,
                   std::optional<std::string_view> dataset, Serve serve) {
  StatusOr<Admission> admission =
      app->Admit(AuthorizationOf(*context), scope, dataset);
  if (!admission.ok()) {
    return Refuse(context, admission.status(), std::type_identity<Reactor>());
  }
  return serve(*std::move(admission));
}

}  // namespace

grpc::ServerUnaryReactor* LocatorService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        return FinishNow(context, app_->Locate(call, *request, response));
      });
}

grpc::ServerUnaryReactor* LocatorService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        app_->LocateBatch(
            std::move(call), *request,
            UnaryCallControl(context, reactor, app_->default_deadline()),
            response);
        return reactor;
      });
}

StreamReactor* LocatorService::LocateStream(
    grpc::CallbackServerContext* context) {
  return AdmitThen<StreamReactor>(
      app_, context, AccessPolicy::Scope::kData, std::nullopt,
      [&](Admission call) {
        // The reactor holds the function (and with it the admission and the
        // engines the stream resolved) until done. Its reactions run one at
        // a time, so `resolved` needs no lock of its own.
        return new LocateStreamReactor(
            context, app_->default_deadline(),
            AnswerAtOnce([app = app_, call = std::move(call),
                          resolved = std::map<const DatasetSlot*, Admission>()](
                             const v1::LocateRequest& request,
                             LocateResult* result) mutable -> Status {
              StatusOr<Admission> dataset = app->Resolve(request.dataset());
              if (!dataset.ok()) return dataset.status();
              const Admission& pinned =
                  resolved.try_emplace(dataset->dataset, *std::move(dataset))
                      .first->second;
              return app->LocateOn(pinned, request, result);
            }));
      });
}

grpc::ServerUnaryReactor* LocatorService::GetStats(
    grpc::CallbackServerContext* context, const v1::GetStatsRequest* request,
    v1::GetStatsResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        app_->GetStats(call, response);
        return FinishNow(context, Status::OK());
      });
}

grpc::ServerUnaryReactor* LocatorService::Retune(
    grpc::CallbackServerContext* context, const v1::RetuneRequest* request,
    v1::RetuneResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kAdmin, request->dataset(),
      [&](Admission call) {
        app_->Retune(call, response);
        return FinishNow(context, Status::OK());
      });
}

grpc::ServerUnaryReactor* LocatorService::Reload(
    grpc::CallbackServerContext* context, const v1::ReloadRequest* request,
    v1::ReloadResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kAdmin, request->name(),
      [&](Admission call) {
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        app_->Reload(std::move(call), *request, response,
                     [reactor](const Status& status) {
                       reactor->Finish(ToGrpcStatus(status));
                     });
        return reactor;
      });
}

grpc::ServerUnaryReactor* LocatorService::GetTopology(
    grpc::CallbackServerContext* context, const v1::GetTopologyRequest* request,
    v1::GetTopologyResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        app_->GetTopology(call, response);
        return FinishNow(context, Status::OK());
      });
}

grpc::ServerUnaryReactor* LocatorService::ListDatasets(
    grpc::CallbackServerContext* context,
    const v1::ListDatasetsRequest* /*request*/,
    v1::ListDatasetsResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kData, std::nullopt,
      [&](Admission /*call*/) {
        app_->ListDatasets(response);
        return FinishNow(context, Status::OK());
      });
}

grpc::ServerUnaryReactor* LocatorService::Profile(
    grpc::CallbackServerContext* context, const v1::ProfileRequest* request,
    v1::ProfileResponse* response) {
  return AdmitThen<grpc::ServerUnaryReactor>(
      app_, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) {
        grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
        app_->surface_pool().Submit([app = app_, reactor, request, response,
                                     call = std::move(call)] {
          reactor->Finish(ToGrpcStatus(app->Profile(call, *request, response)));
        });
        return reactor;
      });
}

GridReactor* LocatorService::Grid(grpc::CallbackServerContext* context,
                                  const v1::GridRequest* request) {
  return AdmitThen<GridReactor>(
      app_, context, AccessPolicy::Scope::kData, request->dataset(),
      [&](Admission call) -> GridReactor* {
        StatusOr<RasterSpec> spec = app_->GridSpec(call, *request);
        if (!spec.ok()) return new RejectedReactor<GridReactor>(spec.status());
        std::shared_ptr<const Engine> engine = call.engine;
        const std::string crs = engine->dataset_info().crs;
        return new GridStream(
            context, DeadlineOf(*context, app_->default_deadline()),
            std::move(engine), *spec, crs, &app_->surface_pool(),
            std::make_shared<Admission>(std::move(call)));
      });
}

}  // namespace locator
