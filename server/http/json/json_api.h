// JsonApi: locator.v1 over HTTP/JSON, for web frontends, on locatord's HTTP
// server:
//
//   GET  /v1/datasets                      ListDatasetsRequest (no body)
//                                          -> ListDatasetsResponse
//   POST /v1/datasets/{name}:locate        LocateRequest -> LocateResponse
//   POST /v1/datasets/{name}:locateBatch   LocateBatchRequest
//                                          -> LocateBatchResponse
//   POST /v1/datasets/{name}:profile       ProfileRequest -> ProfileResponse
//   POST /v1/datasets/{name}:grid          GridRequest -> one GridResponse
//                                          holding the header and every row
//                                          (the gRPC call streams them)
//   GET  /v1/datasets/{name}:topology      GetTopologyRequest (no body)
//                                          -> GetTopologyResponse
//
//   GET  /v1/datasets/{name}/tiles/{z}/{x}/{y}.png?encoding=terrarium|mapbox
//                                          a terrain tile (see tile_api.cc)
//   GET  /v1/datasets/{name}/tiles.json?encoding=...
//                                          its TileJSON 3.0.0
//   GET  /v1/datasets/{name}/hillshade/{z}/{x}/{y}.png?azimuth=&altitude=
//        &z_factor=&scale=                 a shaded relief tile
//   GET  /v1/datasets/{name}/quantized-mesh/{z}/{x}/{y}.terrain
//                                          Cesium terrain (see
//                                          quantized_mesh_api.cc)
//   GET  /v1/datasets/{name}/quantized-mesh/layer.json
//                                          its layer.json
//
// Bodies are the proto messages in protobuf's JSON mapping (JsonFormat):
// requests are parsed with JsonStringToMessage (field names as in the proto
// or lowerCamelCase; an empty body is {}; unknown fields are errors) and
// answers printed with ProtoJson (proto field names, every field present,
// 64-bit integers as strings, NaN as "NaN"). {name} sets the request's
// `dataset`; a body naming another dataset is INVALID_ARGUMENT.
//
// Every call is admitted by LocatorApp::Admit, as a gRPC call is (the
// "authorization: Bearer <token>" header, the same scopes, the drain), and
// runs the application's own method (a grid: GridSpec and GridJson), so
// the answers, limits and errors are the gRPC ones, and a :grid is also held
// to JsonApiOptions::max_grid_cells, since its answer is one JSON text. An
// error is the Status as an ApiError (HTTP status by HttpStatusFor);
// malformed JSON is 400 naming the parse error, an unknown path 404, a
// method a path does not take 405 with Allow. HTTP carries no deadline, so
// every call is held to the server's default deadline from its arrival
// (504 past it): a call still queued then is not run, and a batch or grid
// stops between blocks.
//
// Admission and ListDatasets run on the HTTP server's thread; the dataset
// methods in one of two lanes (ApiLane): "cheap" (kCheapThreads threads)
// runs :locate and a :locateBatch of at most kCheapBatchBodyBytes, and
// "expensive" (kExpensiveThreads) runs the larger batches, :profile and
// :grid, so that a cheap call never waits behind an expensive one. A large
// batch also uses the service's batch workers. A call that finds
// JsonApiOptions::max_waiting_calls calls queued in its lane is refused
// with 503 UNAVAILABLE and Retry-After, as a connection over the server's
// limits is.
//
// The server's other HTTP APIs (Open Topo Data, OGC API - EDR) run their
// calls in the same lanes through RunCall(), so that the limits, gauges and
// the drain at Shutdown() cover them too.
//
// Owns its lanes. Thread-safety: Handle(), RunCall() and Shutdown() may be
// called from any thread.

#ifndef LOCATOR_SERVER_HTTP_JSON_API_H_
#define LOCATOR_SERVER_HTTP_JSON_API_H_

#include <prometheus/registry.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "server/app/locator_app.h"
#include "server/http/api_lane.h"
#include "server/http/http_server.h"
#include "server/serving/call_deadline.h"
#include "server/serving/drain_gate.h"

namespace locator {

struct JsonApiOptions {
  // A :grid of more cells fails with RESOURCE_EXHAUSTED
  // (--http-max-grid-cells): its answer is one JSON text of about 20 bytes
  // per cell, so the default keeps it near 20 MB.
  uint64_t max_grid_cells = uint64_t{1} << 20;
  // A dataset method that finds this many calls queued in its lane is
  // refused with UNAVAILABLE (503, Retry-After) instead of queued
  // (--http-max-waiting-calls).
  size_t max_waiting_calls = 64;
};

class JsonApi {
 public:
  static constexpr size_t kCheapThreads = 2;
  static constexpr size_t kExpensiveThreads = 1;
  // A :locateBatch body up to this size (a few thousand points) is cheap.
  static constexpr size_t kCheapBatchBodyBytes = 64 * 1024;
  // Where the API's paths start.
  static constexpr std::string_view kPathPrefix = "/v1/";
  // Where a dataset's Cesium terrain starts, after its name.
  static constexpr std::string_view kQuantizedMeshPrefix = "/quantized-mesh/";

  // Serves `app` (not owned; it must outlive the API) within `options`,
  // with the lanes' gauges in `registry` (null: a registry of its own,
  // which nothing reads).
  explicit JsonApi(LocatorApp* app, JsonApiOptions options = {},
                   prometheus::Registry* registry = nullptr);
  // Shutdown().
  ~JsonApi();

  JsonApi(const JsonApi&) = delete;
  JsonApi& operator=(const JsonApi&) = delete;

  // Answers `request` (a path under kPathPrefix) through `reply`.
  void Handle(HttpRequest request, HttpReply reply);

  // Answers later calls UNAVAILABLE "server is shutting down" at once, and
  // waits until every call accepted before has been replied to, so that
  // the HTTP server their replies go to may be stopped then.
  void Shutdown();

  // Runs `run` for a call of another of the server's HTTP APIs (Open Topo
  // Data, OGC API EDR) in this API's expensive or cheap lane, as this API's
  // own calls run: counted for Shutdown() until `reply` is called, and on
  // the lanes' gauges. `run` gets OK and the reply on a lane thread, or the
  // refusal (UNAVAILABLE: shutting down or the lane full; DEADLINE_EXCEEDED:
  // `deadline` passed while queued) for the caller to answer in its form.
  using LaneCall = std::function<void(const Status& admitted, HttpReply reply)>;
  void RunCall(bool expensive, const CallDeadline& deadline, HttpReply reply,
               LaneCall run);

  // The API method of a dataset: POST /v1/datasets/{name}:{method}. Runs
  // in a lane with the admitted call, its deadline and the request whose
  // body it parses, and answers through `reply`.
  using DatasetMethod = void (JsonApi::*)(LocatorApp::Admission call,
                                          const CallDeadline& deadline,
                                          const HttpRequest& request,
                                          HttpReply reply);

 private:
  // A unary call: parses the body into Request, runs `run` and answers its
  // Response.
  template <typename Request, typename Response, auto run>
  void ServeUnary(LocatorApp::Admission call, const CallDeadline& deadline,
                  const HttpRequest& request, HttpReply reply);
  void ServeLocateBatch(LocatorApp::Admission call,
                        const CallDeadline& deadline,
                        const HttpRequest& request, HttpReply reply);
  void ServeGrid(LocatorApp::Admission call, const CallDeadline& deadline,
                 const HttpRequest& request, HttpReply reply);
  // POST /v1/datasets/{name}:{method}.
  void ServeDatasetMethod(HttpRequest request, std::string name,
                          std::string method, HttpReply reply);
  // A GET answered by `answer` once the call is admitted for `dataset`
  // (nullopt: a call about no single dataset): GET /v1/datasets and
  // GET /v1/datasets/{name}:topology. 405 for another method, the
  // admission's refusal as its status.
  void ServeGet(
      const HttpRequest& request, std::optional<std::string_view> dataset,
      HttpReply reply,
      const std::function<HttpResponse(const LocatorApp::Admission&)>& answer);
  // GET /v1/datasets/{name}/{rest}: the terrain tiles and their TileJSON,
  // and the hillshade tiles (tile_api.cc).
  void ServeTiles(HttpRequest request, std::string name, std::string rest,
                  HttpReply reply);
  // GET /v1/datasets/{name}/quantized-mesh/{rest}: Cesium terrain and its
  // layer.json (quantized_mesh_api.cc).
  void ServeQuantizedMesh(HttpRequest request, std::string name,
                          std::string rest, HttpReply reply);
  // The "{z}/{x}/{y}" of a tile path split at its two slashes into
  // `parts`; false unless there are exactly two.
  static bool SplitTilePath(std::string_view zxy,
                            std::array<std::string_view, 3>* parts);
  // The admission of a GET of dataset `name`'s tiles: nullopt, once
  // `reply` has the refusal, for another method (405) or a call the
  // application does not admit.
  std::optional<LocatorApp::Admission> AdmitTileGet(const HttpRequest& request,
                                                    const std::string& name,
                                                    HttpReply& reply) const;
  // The Cache-Control of tiles: public unless the server wants a token
  // for data, so that no shared cache hands them to someone without one.
  std::string TileCacheControl() const;
  // Runs `serve` in `lane` with `reply`, unless the lane is full (503) or
  // `deadline` passed while it waited (504).
  void RunInLane(ApiLane& lane, const CallDeadline& deadline, HttpReply reply,
                 std::function<void(HttpReply reply)> serve);
  // Runs `run` in `lane` with OK, or with the refusal RunCall() describes.
  void SubmitToLane(ApiLane& lane, const CallDeadline& deadline,
                    HttpReply reply, LaneCall run);

  // The method table: one line per API method of a dataset. A call whose
  // body has at most cheap_up_to_bytes runs in the cheap lane.
  struct DatasetRoute {
    std::string_view method;
    AccessPolicy::Scope scope;
    DatasetMethod serve;
    size_t cheap_up_to_bytes;
  };
  static const DatasetRoute kDatasetRoutes[];

  LocatorApp* const app_;
  const JsonApiOptions options_;
  // Counts the calls whose reply is pending, for the destructor.
  DrainGate pending_;
  std::shared_ptr<prometheus::Registry> own_registry_;  // when given none
  prometheus::Family<prometheus::Gauge>& running_;
  prometheus::Family<prometheus::Gauge>& waiting_;
  ApiLane cheap_;  // last two: stopped first
  ApiLane expensive_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_JSON_API_H_
