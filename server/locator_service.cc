#include "server/locator_service.h"

#include <utility>

#include "server/locate_stream_reactor.h"
#include "server/proto_convert.h"
#include "server/status_mapping.h"

namespace locator {
namespace {

grpc::Status LoadingStatus() {
  return grpc::Status(grpc::StatusCode::UNAVAILABLE,
                      "dataset is still loading");
}

// Ends a stream at once, before reading anything.
class RejectedStreamReactor final
    : public grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse> {
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

}  // namespace

LocatorService::LocatorService(const LocatorServiceOptions& options)
    : batch_locator_(options.batch_threads, options.max_batch_points),
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
  std::lock_guard<std::mutex> lock(engine_mu_);
  engine_ = std::move(engine);
  return ++generation_;
}

std::shared_ptr<Engine> LocatorService::engine() const {
  std::lock_guard<std::mutex> lock(engine_mu_);
  return engine_;
}

std::shared_ptr<Engine> LocatorService::engine(uint64_t* generation) const {
  std::lock_guard<std::mutex> lock(engine_mu_);
  *generation = generation_;
  return engine_;
}

Status LocatorService::StartReload(const std::string& dataset,
                                   EngineReloader::Done done) {
  return reloader_.Start(dataset, std::move(done));
}

grpc::ServerUnaryReactor* LocatorService::Locate(
    grpc::CallbackServerContext* context, const v1::LocateRequest* request,
    v1::LocateResponse* response) {
  std::shared_ptr<Engine> engine = this->engine();
  if (engine == nullptr) return FinishNow(context, LoadingStatus());
  LocateResult result;
  const Status status = engine->Locate(
      Point2{request->point().x(), request->point().y()}, &result);
  if (status.ok()) ToLocateResponse(result, response);
  return FinishNow(context, ToGrpcStatus(status));
}

grpc::ServerUnaryReactor* LocatorService::LocateBatch(
    grpc::CallbackServerContext* context, const v1::LocateBatchRequest* request,
    v1::LocateBatchResponse* response) {
  std::shared_ptr<Engine> engine = this->engine();
  if (engine == nullptr) return FinishNow(context, LoadingStatus());
  return batch_locator_.Serve(
      context, *request,
      [engine](std::span<const Point2> points,
               std::vector<LocateResult>* results,
               const std::function<bool()>& keep_going) {
        return engine->LocateBatch(points, results, keep_going);
      },
      response);
}

grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>*
LocatorService::LocateStream(grpc::CallbackServerContext* /*context*/) {
  std::shared_ptr<Engine> engine = this->engine();
  if (engine == nullptr) {
    return new RejectedStreamReactor(LoadingStatus());
  }
  return new LocateStreamReactor(
      [engine](const Point2& point, LocateResult* result) {
        return engine->Locate(point, result);
      });
}

grpc::ServerUnaryReactor* LocatorService::GetStats(
    grpc::CallbackServerContext* context,
    const v1::GetStatsRequest* /*request*/, v1::GetStatsResponse* response) {
  uint64_t generation = 0;
  std::shared_ptr<Engine> engine = this->engine(&generation);
  if (engine == nullptr) return FinishNow(context, LoadingStatus());
  ToGetStatsResponse(engine->Stats(), response);
  response->set_generation(generation);
  response->set_reload_in_progress(reloader_.in_progress());
  return FinishNow(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* LocatorService::Retune(
    grpc::CallbackServerContext* context, const v1::RetuneRequest* /*request*/,
    v1::RetuneResponse* response) {
  std::shared_ptr<Engine> engine = this->engine();
  if (engine == nullptr) return FinishNow(context, LoadingStatus());
  engine->Retune();
  ToTuningStats(engine->Stats().tuning, /*include_histogram=*/false,
                response->mutable_tuning());
  return FinishNow(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* LocatorService::Reload(
    grpc::CallbackServerContext* context, const v1::ReloadRequest* request,
    v1::ReloadResponse* response) {
  if (engine() == nullptr) return FinishNow(context, LoadingStatus());
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  // The reload thread finishes the call.
  const Status started = StartReload(
      request->dataset(),
      [reactor, response](const Status& status, std::shared_ptr<Engine> engine,
                          uint64_t generation) {
        if (status.ok())
          ToReloadResponse(engine->Stats(), generation, response);
        reactor->Finish(ToGrpcStatus(status));
      });
  if (!started.ok()) reactor->Finish(ToGrpcStatus(started));
  return reactor;
}

}  // namespace locator
