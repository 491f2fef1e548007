// RpcMetrics: Prometheus series for every gRPC call the server finishes,
// fed by a server interceptor (NewInterceptorFactory()), so that every
// service and method is counted without code in the handlers.
//
// Owns nothing but pointers into the families it adds to `registry`:
//   locator_rpc_requests_total{service,method,code}  finished calls
//   locator_rpc_errors_total{service,method,code}    the non-OK ones
//   locator_rpc_duration_seconds{service,method}     start to status sent
// A series is created the first time its labels occur.
//
// Invariant: the label values come from a fixed set. Only the methods the
// server serves (given at construction) are labelled by name; a call of
// any other method, whose name the client chose, is counted under
// service="unknown", method="unknown", so that clients cannot grow the
// series (and /metrics) without bound. Codes are gRPC's 17.
//
// Thread-safety: Record() and the interceptors may run on any number of
// threads at once; lookups of existing series take a shared lock only.

#ifndef LOCATOR_SERVER_METRICS_RPC_METRICS_H_
#define LOCATOR_SERVER_METRICS_RPC_METRICS_H_

#include <grpcpp/grpcpp.h>
#include <grpcpp/support/server_interceptor.h>
#include <prometheus/counter.h>
#include <prometheus/family.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/mutex.h"

namespace locator {

class RpcMetrics {
 public:
  // The service and method label of calls of methods not served.
  static constexpr std::string_view kUnknown = "unknown";

  // Adds the families above to `registry`, which must outlive this object.
  // `methods` are those served, as "/package.Service/Method".
  RpcMetrics(prometheus::Registry* registry,
             const std::vector<std::string>& methods);

  RpcMetrics(const RpcMetrics&) = delete;
  RpcMetrics& operator=(const RpcMetrics&) = delete;

  // Counts one call of `method` ("/package.Service/Method") that ended with
  // `code` after `seconds`.
  void Record(std::string_view method, grpc::StatusCode code, double seconds)
      EXCLUDES(mu_);

  // A factory for grpc::ServerBuilder's interceptors that calls Record()
  // once per call. This object must outlive the server.
  std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>
  NewInterceptorFactory();

 private:
  // The series one (method, code) pair updates.
  struct Series {
    prometheus::Counter* requests = nullptr;
    prometheus::Counter* errors = nullptr;  // null for OK
    prometheus::Histogram* duration = nullptr;
  };
  // Indexed by status code (0..16).
  using MethodSeries = std::array<Series, 17>;

  // The series of (method, code), created on first use.
  const Series& SeriesFor(std::string_view method, grpc::StatusCode code)
      EXCLUDES(mu_);
  // The series of `method`: its own if it is served, else unknown_.
  MethodSeries& SeriesOf(std::string_view method) REQUIRES_SHARED(mu_);

  prometheus::Family<prometheus::Counter>& requests_;
  prometheus::Family<prometheus::Counter>& errors_;
  prometheus::Family<prometheus::Histogram>& duration_;

  SharedMutex mu_;
  // One entry per served method; the keys are fixed at construction.
  std::map<std::string, MethodSeries, std::less<>> by_method_ GUARDED_BY(mu_);
  MethodSeries unknown_ GUARDED_BY(mu_);
};

}  // namespace locator

#endif  // LOCATOR_SERVER_METRICS_RPC_METRICS_H_
