#include "server/app/locator_app.h"

#include <algorithm>
#include <utility>

#include "common/status_macros.h"
#include "server/app/proto_convert.h"
#include "server/app/query_options.h"
#include "server/app/request_crs.h"
#include "server/app/surface_convert.h"
#include "server/serving/stats_redaction.h"

namespace locator {
namespace {

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

LocatorApp::LocatorApp(const LocatorAppOptions& options)
    : default_deadline_(options.default_deadline),
      max_profile_crossings_(options.max_profile_crossings),
      max_profile_samples_(options.max_profile_samples),
      max_grid_cells_(options.max_grid_cells),
      redact_(options.access.redact),
      access_(options.access.data_token, options.access.admin_token),
      batch_locator_(options.batch_threads, options.max_batch_points),
      surface_pool_(std::max<size_t>(1, options.batch_threads)),
      registry_(options.datasets, options.reload_dir, options.build_engine) {}

StatusOr<LocatorApp::Admission> LocatorApp::Resolve(
    std::string_view name) const {
  DatasetSlot* slot = nullptr;
  RETURN_IF_ERROR(registry_.Find(name, &slot));
  DatasetSlot::Serving serving = slot->serving();
  if (serving.engine == nullptr) {
    return Status::Unavailable("dataset '" + slot->name() +
                               "' is still loading");
  }
  Admission admission;
  admission.dataset = slot;
  admission.engine = std::move(serving.engine);
  admission.tiles = std::move(serving.tiles);
  admission.generation = serving.generation;
  return admission;
}

StatusOr<v1::GetStatsResponse> LocatorApp::CurrentStats(
    std::string_view dataset) const {
  ASSIGN_OR_RETURN(const Admission current, Resolve(dataset));
  v1::GetStatsResponse stats;
  GetStats(current, &stats);
  return stats;
}

StatusOr<std::shared_ptr<Engine>> LocatorApp::ServingEngine(
    std::string_view dataset) const {
  ASSIGN_OR_RETURN(Admission current, Resolve(dataset));
  return std::move(current.engine);
}

EngineStats LocatorApp::OutputStats(const Engine& engine) const {
  return redact_ ? RedactStats(engine.Stats()) : engine.Stats();
}

void LocatorApp::FillStats(const DatasetSlot& dataset, const Engine& engine,
                           uint64_t generation,
                           v1::GetStatsResponse* response) const {
  ToGetStatsResponse(OutputStats(engine), response);
  response->mutable_dataset()->set_name(dataset.name());
  response->set_generation(generation);
  response->set_reload_in_progress(dataset.reload_in_progress());
}

void LocatorApp::Drain(std::chrono::system_clock::time_point deadline) {
  drain_gate_.Close();
  drain_gate_.WaitUntilIdle(deadline);
}

StatusOr<LocatorApp::Admission> LocatorApp::Admit(
    std::optional<std::string_view> authorization, AccessPolicy::Scope scope,
    std::optional<std::string_view> dataset) {
  DrainGate::Ticket ticket = drain_gate_.Enter();
  if (ticket == nullptr) {
    return Status::Unavailable("server is shutting down");
  }
  RETURN_IF_ERROR(access_.CheckAuthorization(authorization, scope));
  Admission admission;
  if (dataset.has_value()) {
    ASSIGN_OR_RETURN(admission, Resolve(*dataset));
  }
  admission.ticket = std::move(ticket);
  return admission;
}

Status LocatorApp::LocateOn(const Admission& call,
                            const v1::LocateRequest& request,
                            LocateResult* result) const {
  ASSIGN_OR_RETURN(const Point2 point, FromLocateRequest(request));
  ASSIGN_OR_RETURN(const QueryOptions options, QueryOptionsOf(request));
  return LocateInRequestCrs(*call.engine, call.tiles.get(), point, options,
                            result);
}

Status LocatorApp::Locate(const Admission& call,
                          const v1::LocateRequest& request,
                          v1::LocateResponse* response) const {
  LocateResult result;
  RETURN_IF_ERROR(LocateOn(call, request, &result));
  ToLocateResponse(result, response);
  return Status::OK();
}

void LocatorApp::LocateBatch(Admission call,
                             const v1::LocateBatchRequest& request,
                             BatchLocator::CallControl control,
                             v1::LocateBatchResponse* response,
                             BatchFor batch_for) {
  StatusOr<QueryOptions> options = QueryOptionsOf(request);
  if (!options.ok()) {
    control.finish(options.status());
    return;
  }
  const Engine& engine = *call.engine;
  const std::string crs = options->crs;
  // The function (and with it the admission) lives until the batch ends.
  // Each block is transformed where it is located, on its shard's thread.
  batch_locator_.Run(
      request,
      [call = std::move(call), options = *std::move(options), batch_for](
          std::span<Point2> points, size_t first_index,
          std::vector<LocateResult>* results,
          const std::function<bool()>& keep_going) {
        if (batch_for == BatchFor::kElevation) {
          return LocateBatchWhereDefined(*call.engine, options, points, results,
                                         keep_going);
        }
        RETURN_IF_ERROR(
            PointsInDatasetCrs(*call.engine, options.crs, points, first_index));
        if (call.tiles != nullptr) {
          RETURN_IF_ERROR(call.tiles->CheckServed(points, first_index));
        }
        return call.engine->LocateBatch(points, results, keep_going,
                                        options.interpolation, options.detail);
      },
      std::move(control), response,
      [&engine, &crs] { return CheckRequestCrs(engine, crs); });
}

void LocatorApp::GetTopology(const Admission& call,
                             v1::GetTopologyResponse* response) const {
  ToGetTopologyResponse(call.dataset->name(), call.engine->dataset_info().crs,
                        call.tiles.get(), response);
}

void LocatorApp::ListDatasets(v1::ListDatasetsResponse* response) const {
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

void LocatorApp::GetStats(const Admission& call,
                          v1::GetStatsResponse* response) const {
  FillStats(*call.dataset, *call.engine, call.generation, response);
}

void LocatorApp::Retune(const Admission& call,
                        v1::RetuneResponse* response) const {
  call.engine->Retune();
  ToTuningStats(OutputStats(*call.engine).tuning,
                /*include_histogram=*/false, response->mutable_tuning());
}

void LocatorApp::Reload(Admission call, const v1::ReloadRequest& request,
                        v1::ReloadResponse* response,
                        std::function<void(const Status&)> done) {
  DatasetSlot* dataset = call.dataset;
  StatusOr<std::string> from_request = FromReloadRequest(request);
  if (!from_request.ok()) {
    done(from_request.status());
    return;
  }
  const std::string requested = *std::move(from_request);
  StatusOr<std::string> spec = dataset->reload_policy().Resolve(requested);
  if (!spec.ok()) {
    done(spec.status());
    return;
  }
  // The reload thread finishes the call; the admission it holds until then
  // keeps a drain waiting for the build.
  const Status started = dataset->StartReload(
      *spec,
      [this, done, response, requested, spec = *spec, call = std::move(call)](
          const Status& status, std::shared_ptr<Engine> engine,
          uint64_t generation) {
        if (status.ok()) {
          ToReloadResponse(OutputStats(*engine), generation, response);
          response->mutable_dataset()->set_name(call.dataset->name());
        }
        done(redact_ ? status.WithMessage(RedactedReloadError(
                           *call.dataset, requested, spec, status))
                     : status);
      });
  if (!started.ok()) done(started);
}

}  // namespace locator
