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
//
// Bodies are the proto messages in protobuf's JSON mapping (JsonFormat):
// requests are parsed with JsonStringToMessage (field names as in the proto
// or lowerCamelCase; an empty body is {}; unknown fields are errors) and
// answers printed with ProtoJson (proto field names, every field present,
// 64-bit integers as strings, NaN as "NaN"). {name} sets the request's
// `dataset`; a body naming another dataset is INVALID_ARGUMENT.
//
// Every call is admitted by LocatorService::Admit, as a gRPC call is (the
// "authorization: Bearer <token>" header, the same scopes, the drain), and
// runs the service's own Run*() method, so the answers, limits and errors
// are the gRPC ones. An error is the gRPC status as an ApiError (HTTP status
// by HttpStatusFor); malformed JSON is 400 naming the parse error, an
// unknown path 404, a method a path does not take 405 with Allow. A
// LocateBatch is held to the server's default deadline (504 past it): HTTP
// carries none of its own.
//
// Admission runs on the HTTP server's thread; parsing, locating and
// printing on the API's own worker threads (kThreads), and a large batch
// also on the service's batch workers.
//
// Owns its workers. Thread-safety: Handle() and Shutdown() may be called
// from any thread.

#ifndef LOCATOR_SERVER_HTTP_JSON_API_H_
#define LOCATOR_SERVER_HTTP_JSON_API_H_

#include <cstddef>
#include <string_view>

#include "server/drain_gate.h"
#include "server/http/http_server.h"
#include "server/locator_service.h"
#include "server/worker_pool.h"

namespace locator {

class JsonApi {
 public:
  // Threads that parse, run and print API calls.
  static constexpr size_t kThreads = 2;
  // Where the API's paths start.
  static constexpr std::string_view kPathPrefix = "/v1/";

  // Serves `service` (not owned; it must outlive the API).
  explicit JsonApi(LocatorService* service);
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

  // The API method of a dataset: POST /v1/datasets/{name}:{method}. Runs
  // on a worker with the admitted call and the request whose body it
  // parses, and answers through `reply`.
  using DatasetMethod = void (JsonApi::*)(LocatorService::Admission call,
                                          const HttpRequest& request,
                                          HttpReply reply);

 private:
  // A unary call: parses the body into Request, runs `run` and answers its
  // Response.
  template <typename Request, typename Response, auto run>
  void ServeUnary(LocatorService::Admission call, const HttpRequest& request,
                  HttpReply reply);
  void ServeLocateBatch(LocatorService::Admission call,
                        const HttpRequest& request, HttpReply reply);
  // POST /v1/datasets/{name}:{method}.
  void ServeDatasetMethod(HttpRequest request, std::string name,
                          std::string method, HttpReply reply);
  // GET /v1/datasets.
  void ServeListDatasets(const HttpRequest& request, HttpReply reply);

  // The method table: one line per API method of a dataset.
  struct DatasetRoute {
    std::string_view method;
    AccessPolicy::Scope scope;
    DatasetMethod serve;
  };
  static const DatasetRoute kDatasetRoutes[];

  LocatorService* const service_;
  // Counts the calls whose reply is pending, for the destructor.
  DrainGate pending_;
  WorkerPool workers_;  // last: stopped first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_JSON_API_H_
