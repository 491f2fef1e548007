// RouterHttpApi: the router's HTTP/JSON API (locatord --route
// --http-listen), for clients that speak neither gRPC nor GetTopology
// (browsers, curl):
//
//   POST /v1/datasets/{name}:locate        LocateRequest -> LocateResponse
//   POST /v1/datasets/{name}:locateBatch   LocateBatchRequest
//                                          -> LocateBatchResponse
//   POST /v1/datasets/{name}:profile       ProfileRequest -> ProfileResponse
//   POST /v1/datasets/{name}:grid          GridRequest -> one GridResponse
//   GET  /v1/datasets/{name}:topology      -> GetTopologyResponse
//   GET  /metrics                          the router's gRPC calls, as
//                                          locatord's /metrics counts them
//
// in the JSON of locatord's own API (server/http/json/json_api.h: the same
// bodies, answers and error shape, and a :grid held to
// --http-max-grid-cells), routed by ShardRouter. Every other path is 404
// naming these: terrain tiles and the elevation APIs are a shard's. HTTP
// carries no
// deadline: each call gets the router's default (60 s without one), and
// the caller's authorization header goes on to the shards.
//
// Thread-safety: Handle() may be called from any thread.

#ifndef LOCATOR_SERVER_ROUTE_ROUTER_HTTP_API_H_
#define LOCATOR_SERVER_ROUTE_ROUTER_HTTP_API_H_

#include <chrono>
#include <functional>
#include <string>

#include "server/http/http_server.h"
#include "server/route/shard_router.h"

namespace locator {

class RouterHttpApi {
 public:
  // Routes with `router` (which must outlive it); calls get `deadline`.
  // GET /metrics answers `metrics_text()` (the Prometheus text).
  RouterHttpApi(ShardRouter* router, std::chrono::milliseconds deadline,
                std::function<std::string()> metrics_text);

  // Answers `request` through `reply`, possibly on another thread.
  void Handle(HttpRequest request, HttpReply reply);

 private:
  ShardRouter* const router_;
  const std::chrono::milliseconds deadline_;
  const std::function<std::string()> metrics_text_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_ROUTER_HTTP_API_H_
