// CallStarter: one kind of call a load run makes (Locate, LocateBatch,
// NestedBatch.LocateNested), started asynchronously so that a handful of
// gRPC threads keep any number of calls in flight. Each call goes to the
// next channel of a ClientPool with the next queries of a QuerySource.
//
// Refers to the pool and source, which must outlive it. Thread-safety:
// implementations are thread-safe; Start() is called from the runner's
// thread and from gRPC threads as calls end.

#ifndef LOCATOR_CLIENT_LOAD_CALL_STARTER_H_
#define LOCATOR_CLIENT_LOAD_CALL_STARTER_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "client/load/client_pool.h"
#include "client/load/query_source.h"

namespace locator {

class CallStarter {
 public:
  // Runs on a gRPC thread when the call ends, with the server's cost of
  // each point it answered (empty when the call failed).
  using Done = std::function<void(const grpc::Status& status,
                                  std::span<const uint32_t> costs)>;

  CallStarter(ClientPool& pool, QuerySource& source)
      : pool_(pool), source_(source) {}
  virtual ~CallStarter() = default;

  // Starts one call that locates the next `points` queries.
  virtual void Start(size_t points, Done done) = 0;

 protected:
  ClientPool& pool() const { return pool_; }
  QuerySource& source() const { return source_; }

 private:
  ClientPool& pool_;
  QuerySource& source_;
};

// What one call keeps alive until it ends. Starters make it with
// ClientPool::NewCall() and hold it by shared_ptr captured in the
// completion, which gRPC destroys after running it.
template <typename Request, typename Response>
struct InFlightCall {
  grpc::ClientContext context;
  Request request;
  Response response;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_CALL_STARTER_H_
