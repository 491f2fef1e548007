#include "client/load/locator_calls.h"

#include <memory>
#include <utility>

namespace locator {
void UnaryLocateCalls::Start(size_t /*points*/, Done done) {
  auto call =
      pool().NewCall<InFlightCall<v1::LocateRequest, v1::LocateResponse>>();
  const Point2 point = source().Next();
  call->request.mutable_point()->set_x(point.x);
  call->request.mutable_point()->set_y(point.y);
  pool().NextClient().StartLocate(
      &call->context, &call->request, &call->response,
      [call, done = std::move(done)](grpc::Status status) {
        const uint32_t cost = call->response.cost().total();
        done(status, status.ok() ? std::span<const uint32_t>(&cost, 1)
                                 : std::span<const uint32_t>());
      });
}

BatchLocateCalls::BatchLocateCalls(ClientPool& pool, QuerySource& source,
                                   const BatchColumns& columns)
    : CallStarter(pool, source), columns_(columns) {}

void BatchLocateCalls::Start(size_t points, Done done) {
  auto call =
      pool()
          .NewCall<
              InFlightCall<v1::LocateBatchRequest, v1::LocateBatchResponse>>();
  v1::LocateBatchRequest& request = call->request;
  request.mutable_xs()->Resize(static_cast<int>(points), 0.0);
  request.mutable_ys()->Resize(static_cast<int>(points), 0.0);
  source().Next(
      std::span<double>(request.mutable_xs()->mutable_data(), points),
      std::span<double>(request.mutable_ys()->mutable_data(), points));
  RequestColumns(columns_, &request);
  pool().NextClient().StartLocateBatch(
      &call->context, &request, &call->response,
      [call, done = std::move(done)](grpc::Status status) {
        const auto& costs = call->response.costs();
        done(status, status.ok()
                         ? std::span<const uint32_t>(costs.data(), costs.size())
                         : std::span<const uint32_t>());
      });
}

}  // namespace locator
