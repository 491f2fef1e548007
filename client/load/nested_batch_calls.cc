#include "client/load/nested_batch_calls.h"

#include <utility>

namespace locator {

NestedBatchCalls::NestedBatchCalls(ClientPool& pool, QuerySource& source)
    : CallStarter(pool, source) {
  for (size_t i = 0; i < pool.size(); ++i) {
    stubs_.push_back(bench::v1::NestedBatch::NewStub(pool.channel(i)));
  }
}

void NestedBatchCalls::Start(size_t points, Done done) {
  auto call = pool()
                  .NewCall<InFlightCall<bench::v1::NestedBatchRequest,
                                        bench::v1::NestedBatchResponse>>();
  // One lock on the source per batch, as for LocateBatch, so that the
  // comparison measures the encoding alone.
  std::vector<double> xs(points), ys(points);
  source().Next(xs, ys);
  call->request.mutable_points()->Reserve(static_cast<int>(points));
  for (size_t i = 0; i < points; ++i) {
    v1::Point* added = call->request.add_points();
    added->set_x(xs[i]);
    added->set_y(ys[i]);
  }
  SetDeadlineFromNow(&call->context, pool().deadline());
  stubs_[pool().NextIndex()]->async()->LocateNested(
      &call->context, &call->request, &call->response,
      [call, done = std::move(done)](grpc::Status status) {
        std::vector<uint32_t> costs;
        if (status.ok()) {
          costs.reserve(call->response.results_size());
          for (const v1::LocateResponse& result : call->response.results()) {
            costs.push_back(result.cost().total());
          }
        }
        done(status, costs);
      });
}

}  // namespace locator
