#include "client/load/call_loops.h"

#include <random>
#include <thread>

#include "common/in_flight.h"

namespace locator {
namespace {

class ClosedLoop {
 public:
  ClosedLoop(CallStarter& calls, size_t points_per_call, RunBudget& budget,
             RunRecorder& recorder)
      : calls_(calls),
        points_per_call_(points_per_call),
        budget_(budget),
        recorder_(recorder) {}

  void Run(size_t concurrency) {
    for (size_t i = 0; i < concurrency; ++i) {
      chains_.Add();
      StartNext();
    }
    chains_.WaitUntilNone();
  }

 private:
  // Starts a chain's next call, or ends the chain when the budget is spent.
  // Runs on a gRPC thread for every call but the first.
  void StartNext() {
    const LoadClock::time_point start = LoadClock::now();
    Claim claim;
    if (!budget_.TryClaim(points_per_call_, start, &claim)) {
      chains_.Remove();
      return;
    }
    calls_.Start(
        claim.points, [this, claim, start](const grpc::Status& status,
                                           std::span<const uint32_t> costs) {
          recorder_.RecordCall(claim, start, LoadClock::now(), status, costs);
          // gRPC never runs a client completion inline in the thread that
          // started the call, so this does not recurse.
          StartNext();
        });
  }

  CallStarter& calls_;
  const size_t points_per_call_;
  RunBudget& budget_;
  RunRecorder& recorder_;
  InFlight chains_;
};

}  // namespace

void RunClosedLoop(CallStarter& calls, size_t points_per_call,
                   size_t concurrency, RunBudget& budget,
                   RunRecorder& recorder) {
  ClosedLoop(calls, points_per_call, budget, recorder).Run(concurrency);
}

void RunOpenLoop(CallStarter& calls, size_t points_per_call,
                 double calls_per_second, uint64_t seed, RunBudget& budget,
                 RunRecorder& recorder) {
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> gap_seconds(calls_per_second);
  InFlight calls_in_flight;
  LoadClock::time_point scheduled = LoadClock::now();
  while (true) {
    scheduled += std::chrono::duration_cast<LoadClock::duration>(
        std::chrono::duration<double>(gap_seconds(rng)));
    // Sleeping to an absolute time lets a late wake-up catch up with the
    // schedule instead of stretching it.
    std::this_thread::sleep_until(scheduled);
    Claim claim;
    if (!budget.TryClaim(points_per_call, scheduled, &claim)) break;
    calls_in_flight.Add();
    calls.Start(claim.points, [&, claim, scheduled](
                                  const grpc::Status& status,
                                  std::span<const uint32_t> costs) {
      recorder.RecordCall(claim, scheduled, LoadClock::now(), status, costs);
      calls_in_flight.Remove();
    });
  }
  calls_in_flight.WaitUntilNone();
}

}  // namespace locator
