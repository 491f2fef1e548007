// InFlight: counts what is in flight (calls, streams, call contexts) so that
// its owner can wait until the last one has ended.
//
// Counted() also lets the owner of gRPC channels wait until every call
// context made on them has been deleted: a ClientContext holds its channel,
// and a context let go on a gRPC callback thread must not be the channel's
// last holder. The channel's destructor would then tear down the callback
// thread it runs on (grpc/grpc#37858), which ASAN reports as a double free.
//
// Thread-safety: thread-safe. Invariant: the count is the number of Add()
// calls not yet matched by Remove(), counted items included.

#ifndef LOCATOR_COMMON_IN_FLIGHT_H_
#define LOCATOR_COMMON_IN_FLIGHT_H_

#include <cstddef>
#include <memory>

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

  // Takes `item` and counts it in flight until it has been deleted, on
  // whichever thread lets go of its last shared_ptr.
  template <typename T>
  std::shared_ptr<T> Counted(std::unique_ptr<T> item) {
    Add();
    return std::shared_ptr<T>(item.release(), [this](T* ended) {
      delete ended;
      Remove();
    });
  }

 private:
  Mutex mutex_;
  CondVar none_left_;
  size_t count_ GUARDED_BY(mutex_) = 0;
};

}  // namespace locator

#endif  // LOCATOR_COMMON_IN_FLIGHT_H_
