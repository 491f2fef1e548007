// The no-op server's services: the serving ceiling without geometry.
//
// NoopLocatorService answers locator.v1.Locator with the real service's
// message shapes, through the same conversion, batch and stream code, but
// every point "lies" in one fixed triangle (CannedAnswer). What a load test
// measures against it is therefore the cost of gRPC, protobuf and the service
// plumbing alone. NoopNestedBatchService answers locator.bench.v1.NestedBatch
// with one filled LocateResponse per point, for comparing batch encodings.
//
// Thread-safety: both services may serve any number of calls at once.

#ifndef LOCATOR_BENCH_NOOP_SERVICES_H_
#define LOCATOR_BENCH_NOOP_SERVICES_H_

#include <grpcpp/grpcpp.h>

#include <chrono>

#include "locator/bench/v1/nested_batch.grpc.pb.h"
#include "locator/locate_result.h"
#include "locator/v1/locator.grpc.pb.h"
#include "server/app/batch_locator.h"
#include "server/config/server_config.h"

namespace locator {

// The triangle (0,0), (1,0), (0,1) with ids 0, 1, 2 as triangle 0, seen from
// `q`: type FACE, barycentric (1 - x - y, x, y), value x + y, cost 1 face.
LocateResult CannedAnswer(const Point2& q);

class NoopLocatorService final : public v1::Locator::CallbackService {
 public:
  // Uses config's batch threads, point limit and default deadline, like
  // locatord. No access control: it is a yardstick, not a service.
  explicit NoopLocatorService(const ServingConfig& config);

  grpc::ServerUnaryReactor* Locate(grpc::CallbackServerContext* context,
                                   const v1::LocateRequest* request,
                                   v1::LocateResponse* response) override;
  grpc::ServerUnaryReactor* LocateBatch(
      grpc::CallbackServerContext* context,
      const v1::LocateBatchRequest* request,
      v1::LocateBatchResponse* response) override;
  grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>* LocateStream(
      grpc::CallbackServerContext* context) override;
  // Strategy "noop", everything else zero.
  grpc::ServerUnaryReactor* GetStats(grpc::CallbackServerContext* context,
                                     const v1::GetStatsRequest* request,
                                     v1::GetStatsResponse* response) override;
  // Does nothing.
  grpc::ServerUnaryReactor* Retune(grpc::CallbackServerContext* context,
                                   const v1::RetuneRequest* request,
                                   v1::RetuneResponse* response) override;

 private:
  const std::chrono::milliseconds default_deadline_;
  BatchLocator batch_locator_;
};

class NoopNestedBatchService final
    : public bench::v1::NestedBatch::CallbackService {
 public:
  grpc::ServerUnaryReactor* LocateNested(
      grpc::CallbackServerContext* context,
      const bench::v1::NestedBatchRequest* request,
      bench::v1::NestedBatchResponse* response) override;
};

}  // namespace locator

#endif  // LOCATOR_BENCH_NOOP_SERVICES_H_
