// Phase signal: lets another process split a load run into phases. After
// InstallPhaseSignal(), every SIGUSR1 the process receives starts a new
// phase; the report gives each phase's calls, failures and latency
// percentiles (deploy/local-cluster.sh marks a replica's failure and its
// recovery this way).
//
// The handler only increments a lock-free atomic counter, which is
// async-signal-safe. Thread-safety: install once, from main(), before the
// run; the counter may be read from any thread.

#ifndef LOCATOR_CLIENT_LOAD_PHASE_SIGNAL_H_
#define LOCATOR_CLIENT_LOAD_PHASE_SIGNAL_H_

#include <atomic>
#include <cstdint>

namespace locator {

// Installs the SIGUSR1 handler; returns the counter it increments (phase
// 0 until the first signal).
const std::atomic<uint32_t>& InstallPhaseSignal();

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_PHASE_SIGNAL_H_
