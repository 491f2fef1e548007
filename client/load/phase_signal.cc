#include "client/load/phase_signal.h"

#include <signal.h>

namespace locator {
namespace {

std::atomic<uint32_t> phase{0};
// A handler may only touch lock-free atomics; a mutex could deadlock.
static_assert(std::atomic<uint32_t>::is_always_lock_free);

void StartNextPhase(int /*signal_number*/) {
  phase.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

const std::atomic<uint32_t>& InstallPhaseSignal() {
  struct sigaction action = {};
  action.sa_handler = StartNextPhase;
  sigemptyset(&action.sa_mask);
  // Blocking calls in progress (sleeps, reads) resume instead of failing
  // with EINTR.
  action.sa_flags = SA_RESTART;
  sigaction(SIGUSR1, &action, nullptr);
  return phase;
}

}  // namespace locator
