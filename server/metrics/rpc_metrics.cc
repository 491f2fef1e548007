#include "server/metrics/rpc_metrics.h"

#include <chrono>
#include <mutex>
#include <utility>

#include "common/grpc_code_name.h"

namespace locator {
namespace {

using grpc::experimental::InterceptionHookPoints;

// From 50 us (an answer served from memory) to 10 s (a huge batch).
const prometheus::Histogram::BucketBoundaries& DurationBuckets() {
  static const prometheus::Histogram::BucketBoundaries buckets = {
      0.00005, 0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025,
      0.05,    0.1,    0.25,    0.5,    1,     2.5,    5,     10};
  return buckets;
}

// "/locator.v1.Locator/Locate" -> {"locator.v1.Locator", "Locate"}.
std::pair<std::string, std::string> SplitMethod(std::string_view method) {
  if (!method.empty() && method.front() == '/') method.remove_prefix(1);
  const size_t slash = method.find('/');
  if (slash == std::string_view::npos) return {"", std::string(method)};
  return {std::string(method.substr(0, slash)),
          std::string(method.substr(slash + 1))};
}

// One per call: records the call when its status is about to be sent, or,
// if no status is ever sent (the call was torn down first), as CANCELLED
// when gRPC destroys it.
class RpcMetricsInterceptor final : public grpc::experimental::Interceptor {
 public:
  RpcMetricsInterceptor(RpcMetrics* metrics, std::string_view method)
      : metrics_(metrics),
        method_(method),
        start_(std::chrono::steady_clock::now()) {}

  ~RpcMetricsInterceptor() override {
    if (!recorded_) Finish(grpc::StatusCode::CANCELLED);
  }

  void Intercept(
      grpc::experimental::InterceptorBatchMethods* methods) override {
    if (!recorded_ && methods->QueryInterceptionHookPoint(
                          InterceptionHookPoints::PRE_SEND_STATUS)) {
      Finish(methods->GetSendStatus().error_code());
    }
    methods->Proceed();
  }

 private:
  void Finish(grpc::StatusCode code) {
    recorded_ = true;
    metrics_->Record(
        method_, code,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_)
            .count());
  }

  RpcMetrics* const metrics_;
  const std::string_view method_;  // owned by gRPC, valid for the call
  const std::chrono::steady_clock::time_point start_;
  bool recorded_ = false;
};

class RpcMetricsInterceptorFactory final
    : public grpc::experimental::ServerInterceptorFactoryInterface {
 public:
  explicit RpcMetricsInterceptorFactory(RpcMetrics* metrics)
      : metrics_(metrics) {}

  grpc::experimental::Interceptor* CreateServerInterceptor(
      grpc::experimental::ServerRpcInfo* info) override {
    return new RpcMetricsInterceptor(metrics_, info->method());
  }

 private:
  RpcMetrics* const metrics_;
};

}  // namespace

RpcMetrics::RpcMetrics(prometheus::Registry* registry,
                       const std::vector<std::string>& methods)
    : requests_(prometheus::BuildCounter()
                    .Name("locator_rpc_requests_total")
                    .Help("gRPC calls finished, by method and status code")
                    .Register(*registry)),
      errors_(prometheus::BuildCounter()
                  .Name("locator_rpc_errors_total")
                  .Help("gRPC calls finished with a status other than OK")
                  .Register(*registry)),
      duration_(prometheus::BuildHistogram()
                    .Name("locator_rpc_duration_seconds")
                    .Help("Time from a gRPC call's start to its status")
                    .Register(*registry)) {
  WriterMutexLock lock(&mu_);
  for (const std::string& method : methods) by_method_.try_emplace(method);
}

RpcMetrics::MethodSeries& RpcMetrics::SeriesOf(std::string_view method) {
  const auto found = by_method_.find(method);
  return found != by_method_.end() ? found->second : unknown_;
}

const RpcMetrics::Series& RpcMetrics::SeriesFor(std::string_view method,
                                                grpc::StatusCode code) {
  const size_t index = static_cast<size_t>(code) < MethodSeries().size()
                           ? static_cast<size_t>(code)
                           : static_cast<size_t>(grpc::StatusCode::UNKNOWN);
  {
    ReaderMutexLock lock(&mu_);
    const Series& series = SeriesOf(method)[index];
    if (series.requests != nullptr) return series;
  }
  WriterMutexLock lock(&mu_);
  MethodSeries& all = SeriesOf(method);
  Series& series = all[index];
  if (series.requests != nullptr) return series;  // another thread made it
  const auto [service, name] =
      &all == &unknown_
          ? std::pair(std::string(kUnknown), std::string(kUnknown))
          : SplitMethod(method);
  const prometheus::Labels labels = {{"service", service}, {"method", name}};
  prometheus::Labels with_code = labels;
  with_code.emplace("code", std::string(GrpcCodeName(code)));
  series.requests = &requests_.Add(with_code);
  if (code != grpc::StatusCode::OK) series.errors = &errors_.Add(with_code);
  // The family returns the existing histogram for labels it already has.
  series.duration = &duration_.Add(labels, DurationBuckets());
  return series;
}

void RpcMetrics::Record(std::string_view method, grpc::StatusCode code,
                        double seconds) {
  const Series& series = SeriesFor(method, code);
  series.requests->Increment();
  if (series.errors != nullptr) series.errors->Increment();
  series.duration->Observe(seconds);
}

std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>
RpcMetrics::NewInterceptorFactory() {
  return std::make_unique<RpcMetricsInterceptorFactory>(this);
}

}  // namespace locator
