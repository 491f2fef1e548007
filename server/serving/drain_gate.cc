#include "server/serving/drain_gate.h"

#include <thread>

namespace locator {
namespace {

// Draining happens once per process, on the loop thread, which has nothing
// else to do meanwhile: polling keeps Enter() and the ticket's release free
// of any lock on the serving path.
constexpr std::chrono::milliseconds kIdlePoll{5};

}  // namespace

DrainGate::Ticket DrainGate::Enter() {
  // Counted before the check (all sequentially consistent), so that a call
  // admitted before Close() is always seen by WaitUntilIdle().
  in_flight_->fetch_add(1);
  Ticket ticket(in_flight_.get(),
                [count = in_flight_](const void*) { count->fetch_sub(1); });
  if (closed_.load()) return nullptr;
  return ticket;
}

void DrainGate::Close() { closed_.store(true); }

bool DrainGate::WaitUntilIdle(
    std::chrono::system_clock::time_point deadline) const {
  while (in_flight_->load() > 0) {
    if (std::chrono::system_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(kIdlePoll);
  }
  return true;
}

}  // namespace locator
