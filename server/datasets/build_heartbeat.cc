#include "server/datasets/build_heartbeat.h"

#include <sstream>
#include <utility>

namespace locator {

BuildHeartbeat::BuildHeartbeat(Sink sink,
                               std::chrono::steady_clock::duration interval)
    : sink_(std::move(sink)),
      interval_(interval),
      start_(std::chrono::steady_clock::now()),
      thread_([this] { Run(); }) {}

BuildHeartbeat::~BuildHeartbeat() {
  {
    MutexLock lock(&mu_);
    stopped_ = true;
  }
  stop_signal_.SignalAll();
  thread_.join();
}

void BuildHeartbeat::SetPhase(std::string phase) {
  MutexLock lock(&mu_);
  phase_ = std::move(phase);
  progress_.reset();
}

void BuildHeartbeat::Report(const TinProgress& progress) {
  MutexLock lock(&mu_);
  phase_ = "simplifying";
  progress_ = progress;
}

void BuildHeartbeat::Run() {
  auto next = start_ + interval_;
  while (true) {
    std::ostringstream line;
    {
      MutexLock lock(&mu_);
      while (!stopped_ && std::chrono::steady_clock::now() < next) {
        stop_signal_.WaitUntil(&mu_, next);
      }
      if (stopped_) return;
      const std::chrono::duration<double> seconds =
          std::chrono::steady_clock::now() - start_;
      line << phase_ << " for " << seconds.count() << " s";
      if (progress_) {
        line << ": " << progress_->vertices << " vertices, largest error left "
             << progress_->max_error;
      }
    }
    sink_(line.str());
    // From now, not from the missed deadline: a late line (a loaded
    // machine) is not followed by a burst of catching up.
    next = std::chrono::steady_clock::now() + interval_;
  }
}

}  // namespace locator
