// The CallStarters of the public locator.v1 API: unary Locate and columnar
// LocateBatch, each call on the next channel of a ClientPool with the
// pool's per-call deadline.
//
// Each call owns its context and messages on the heap until it ends.
// Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_LOAD_LOCATOR_CALLS_H_
#define LOCATOR_CLIENT_LOAD_LOCATOR_CALLS_H_

#include "client/load/call_starter.h"
#include "client/locator_client.h"

namespace locator {

// Locate: one point per call (`points` is always 1).
class UnaryLocateCalls : public CallStarter {
 public:
  using CallStarter::CallStarter;
  void Start(size_t points, Done done) override;
};

// LocateBatch: `points` points per call, answering `columns` too.
class BatchLocateCalls : public CallStarter {
 public:
  BatchLocateCalls(ClientPool& pool, QuerySource& source,
                   const BatchColumns& columns);
  void Start(size_t points, Done done) override;

 private:
  const BatchColumns columns_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_LOCATOR_CALLS_H_
