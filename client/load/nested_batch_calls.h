// NestedBatchCalls: the CallStarter of --mode nested-batch. Calls
// locator.bench.v1.NestedBatch/LocateNested (served by locator-noop-server
// only), a batch as one message per point, to compare its encoding cost
// with the columnar LocateBatch.
//
// Owns a NestedBatch stub per channel of the pool; each call gets the
// pool's per-call deadline. Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_LOAD_NESTED_BATCH_CALLS_H_
#define LOCATOR_CLIENT_LOAD_NESTED_BATCH_CALLS_H_

#include <memory>
#include <vector>

#include "client/load/call_starter.h"
#include "locator/bench/v1/nested_batch.grpc.pb.h"

namespace locator {

class NestedBatchCalls : public CallStarter {
 public:
  NestedBatchCalls(ClientPool& pool, QuerySource& source);
  void Start(size_t points, Done done) override;

 private:
  std::vector<std::unique_ptr<bench::v1::NestedBatch::Stub>> stubs_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_NESTED_BATCH_CALLS_H_
