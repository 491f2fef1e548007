// RunStreams: the load run of --mode stream. `streams` LocateStream calls,
// spread over the pool's channels; each keeps up to `window` requests sent
// but not yet answered, sending the next query as an answer comes back.
// Latency runs from sending a request to reading its answer.
//
// A stream is one call, so it gets one deadline: the budget's end plus the
// pool's per-call deadline. Requests still unanswered when a stream fails
// are counted as failed with the stream's status.
//
// Thread-safety: blocks its calling thread until every stream has ended.

#ifndef LOCATOR_CLIENT_LOAD_STREAM_RUNNER_H_
#define LOCATOR_CLIENT_LOAD_STREAM_RUNNER_H_

#include <cstddef>

#include "client/load/client_pool.h"
#include "client/load/query_source.h"
#include "client/load/run_budget.h"
#include "client/load/run_recorder.h"

namespace locator {

void RunStreams(ClientPool& pool, QuerySource& source, size_t streams,
                size_t window, RunBudget& budget, RunRecorder& recorder);

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_STREAM_RUNNER_H_
