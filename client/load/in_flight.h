// InFlight: counts what a runner has in flight (calls or streams) so that it
// can wait until the last one has ended.
//
// Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_LOAD_IN_FLIGHT_H_
#define LOCATOR_CLIENT_LOAD_IN_FLIGHT_H_

#include <condition_variable>
#include <cstddef>
#include <mutex>

namespace locator {

class InFlight {
 public:
  // One more is in flight.
  void Add() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++count_;
  }
  // One has ended.
  void Remove() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (--count_ == 0) none_left_.notify_all();
  }
  // Blocks until none is in flight.
  void WaitUntilNone() {
    std::unique_lock<std::mutex> lock(mutex_);
    none_left_.wait(lock, [this] { return count_ == 0; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable none_left_;
  size_t count_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_IN_FLIGHT_H_
