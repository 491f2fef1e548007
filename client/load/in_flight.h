// InFlight: counts what a runner has in flight (calls or streams) so that it
// can wait until the last one has ended.
//
// Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_LOAD_IN_FLIGHT_H_
#define LOCATOR_CLIENT_LOAD_IN_FLIGHT_H_

#include <cstddef>

#include "common/mutex.h"

namespace locator {

class InFlight {
 public:
  // One more is in flight.
  void Add() EXCLUDES(mutex_) {
    MutexLock lock(&mutex_);
    ++count_;
  }
  // One has ended.
  void Remove() EXCLUDES(mutex_) {
    MutexLock lock(&mutex_);
    if (--count_ == 0) none_left_.SignalAll();
  }
  // Blocks until none is in flight.
  void WaitUntilNone() EXCLUDES(mutex_) {
    MutexLock lock(&mutex_);
    while (count_ != 0) none_left_.Wait(&mutex_);
  }

 private:
  Mutex mutex_;
  CondVar none_left_;
  size_t count_ GUARDED_BY(mutex_) = 0;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_IN_FLIGHT_H_
