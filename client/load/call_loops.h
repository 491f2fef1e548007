// The two ways a load run paces its calls.
//
// Closed loop: `concurrency` chains of calls; each chain starts its next
// call the moment the previous one ends, so exactly that many are in flight
// and the server's speed sets the rate. Latency runs from each call's start.
//
// Open loop: calls start on a schedule of Poisson arrivals at a fixed mean
// rate, whether or not earlier calls have ended. Latency runs from each
// call's *scheduled* start, so a stall that delays sending is charged to the
// calls it delayed (no coordinated omission).
//
// Both return once the budget is spent and every call has ended.
// Thread-safety: each blocks its calling thread; calls end on gRPC threads.

#ifndef LOCATOR_CLIENT_LOAD_CALL_LOOPS_H_
#define LOCATOR_CLIENT_LOAD_CALL_LOOPS_H_

#include <cstddef>
#include <cstdint>

#include "client/load/call_starter.h"
#include "client/load/run_budget.h"
#include "client/load/run_recorder.h"

namespace locator {

// Closed loop with `concurrency` calls of `points_per_call` in flight.
void RunClosedLoop(CallStarter& calls, size_t points_per_call,
                   size_t concurrency, RunBudget& budget,
                   RunRecorder& recorder);

// Open loop at `calls_per_second` on average; `seed` fixes the schedule.
void RunOpenLoop(CallStarter& calls, size_t points_per_call,
                 double calls_per_second, uint64_t seed, RunBudget& budget,
                 RunRecorder& recorder);

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_CALL_LOOPS_H_
