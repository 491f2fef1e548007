#include "server/core/terrain/tin_progress.h"

#include <algorithm>
#include <cmath>

namespace locator {

namespace {

int64_t IntervalNs(const TinOptions& options) {
  return static_cast<int64_t>(options.progress_interval_s * 1e9);
}

}  // namespace

TinProgressReporter::TinProgressReporter(const TinOptions& options,
                                         size_t slots)
    : options_(options),
      start_(std::chrono::steady_clock::now()),
      slots_(std::max<size_t>(slots, 1)),
      vertices_(new std::atomic<uint64_t>[slots_]),
      errors_(new std::atomic<double>[slots_]),
      next_due_ns_(IntervalNs(options)) {
  for (size_t i = 0; i < slots_; ++i) {
    vertices_[i].store(0, std::memory_order_relaxed);
    errors_[i].store(0, std::memory_order_relaxed);
  }
}

double TinProgressReporter::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                       start_)
      .count();
}

void TinProgressReporter::Update(size_t slot, uint64_t vertices, double error) {
  vertices_[slot].store(vertices, std::memory_order_relaxed);
  errors_[slot].store(error, std::memory_order_relaxed);
  Poll();
}

void TinProgressReporter::Merged(uint64_t vertices, double error) {
  for (size_t i = 1; i < slots_; ++i) {
    vertices_[i].store(0, std::memory_order_relaxed);
    errors_[i].store(0, std::memory_order_relaxed);
  }
  Update(0, vertices, error);
}

void TinProgressReporter::Poll() {
  if (!options_.progress) return;
  const int64_t now_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                             std::chrono::steady_clock::now() - start_)
                             .count();
  if (now_ns < next_due_ns_.load(std::memory_order_relaxed)) return;
  MutexLock lock(&mu_);
  if (now_ns < next_due_ns_.load(std::memory_order_relaxed)) return;
  TinProgress progress;
  for (size_t i = 0; i < slots_; ++i) {
    progress.vertices += vertices_[i].load(std::memory_order_relaxed);
    progress.max_error = std::max(progress.max_error,
                                  errors_[i].load(std::memory_order_relaxed));
  }
  progress.seconds = now_ns * 1e-9;
  options_.progress(progress);
  next_due_ns_.store(now_ns + IntervalNs(options_), std::memory_order_relaxed);
}

}  // namespace locator
