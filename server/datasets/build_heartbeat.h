// BuildHeartbeat: keeps a dataset's build visible in the log. While it
// lives, a thread of its own writes one line every `interval`: what the
// build is doing (its phase: "loading", "simplifying", "building the
// serving mesh"), for how long, and while simplifying the simplifier's last
// progress (vertices so far, the largest error left). A long build thus
// says something at least every `interval`, whether or not the step it is
// in reports progress of its own.
//
// Owns the thread; the destructor stops and joins it.
// Thread-safety: SetPhase() and Report() may be called from any thread
// (Report() from the simplifier's building threads); the sink is called
// from the heartbeat's thread only, never with a lock held.

#ifndef LOCATOR_SERVER_BUILD_HEARTBEAT_H_
#define LOCATOR_SERVER_BUILD_HEARTBEAT_H_

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <thread>

#include "common/mutex.h"
#include "common/thread_annotations.h"
#include "server/core/terrain/tin_options.h"

namespace locator {

class BuildHeartbeat {
 public:
  using Sink = std::function<void(const std::string& line)>;

  // Starts the heartbeat in phase "loading"; `sink` gets every line.
  BuildHeartbeat(Sink sink, std::chrono::steady_clock::duration interval);
  ~BuildHeartbeat();

  BuildHeartbeat(const BuildHeartbeat&) = delete;
  BuildHeartbeat& operator=(const BuildHeartbeat&) = delete;

  // The build is now `phase`; the simplifier's progress is forgotten.
  void SetPhase(std::string phase) EXCLUDES(mu_);
  // The simplifier's latest progress; the phase becomes "simplifying".
  void Report(const TinProgress& progress) EXCLUDES(mu_);

 private:
  // Writes a line every interval_ until stopped.
  void Run() EXCLUDES(mu_);

  const Sink sink_;
  const std::chrono::steady_clock::duration interval_;
  const std::chrono::steady_clock::time_point start_;
  Mutex mu_;
  CondVar stop_signal_;
  bool stopped_ GUARDED_BY(mu_) = false;
  std::string phase_ GUARDED_BY(mu_) = "loading";
  std::optional<TinProgress> progress_ GUARDED_BY(mu_);
  // Started last: Run() reads the members above.
  std::thread thread_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_BUILD_HEARTBEAT_H_
