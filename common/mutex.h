// Mutex, MutexLock, CondVar, SharedMutex: std::mutex and friends, annotated
// so that clang's thread-safety analysis (-Wthread-safety, see
// common/thread_annotations.h) can check GUARDED_BY and REQUIRES against the
// locks a function actually holds. Each class owns only its std primitive.
//
// Thread-safety: like the std type each wraps. None is copyable or movable.
//
// Usage:
//   Mutex mu_;
//   int count_ GUARDED_BY(mu_);
//   void Add() EXCLUDES(mu_) { MutexLock lock(&mu_); ++count_; }
//
// A condition is awaited with an explicit loop at the call site, so that the
// analysis sees the guarded reads under the lock (a predicate lambda would be
// analysed on its own, without the lock):
//   MutexLock lock(&mu_);
//   while (count_ != 0) none_left_.Wait(&mu_);

#ifndef LOCATOR_COMMON_MUTEX_H_
#define LOCATOR_COMMON_MUTEX_H_

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <shared_mutex>

#include "common/thread_annotations.h"

namespace locator {

class CAPABILITY("mutex") Mutex {
 public:
  Mutex() = default;
  Mutex(const Mutex&) = delete;
  Mutex& operator=(const Mutex&) = delete;

  // Blocks until this thread holds the mutex.
  void Lock() ACQUIRE() { mu_.lock(); }
  // Releases the mutex, which this thread holds.
  void Unlock() RELEASE() { mu_.unlock(); }
  // Takes the mutex if it is free; returns whether this thread now holds it.
  bool TryLock() TRY_ACQUIRE(true) { return mu_.try_lock(); }

 private:
  friend class CondVar;
  std::mutex mu_;
};

// Holds a Mutex for its lifetime.
class SCOPED_CAPABILITY MutexLock {
 public:
  // Blocks until `mu` is held; `mu` must outlive the lock.
  explicit MutexLock(Mutex* mu) ACQUIRE(mu) : mu_(mu) { mu_->Lock(); }
  // Releases the mutex.
  ~MutexLock() RELEASE() { mu_->Unlock(); }

  MutexLock(const MutexLock&) = delete;
  MutexLock& operator=(const MutexLock&) = delete;

 private:
  Mutex* const mu_;
};

// A condition variable used with a Mutex.
class CondVar {
 public:
  CondVar() = default;
  CondVar(const CondVar&) = delete;
  CondVar& operator=(const CondVar&) = delete;

  // Releases `mu` (held by this thread), blocks until signalled (or a
  // spurious wake-up) and takes `mu` again before returning.
  void Wait(Mutex* mu) REQUIRES(mu) {
    std::unique_lock<std::mutex> lock(mu->mu_, std::adopt_lock);
    cv_.wait(lock);
    lock.release();  // the caller still holds mu
  }
  // As Wait(), but returns false once `deadline` has passed without a
  // signal (true otherwise, spurious wake-ups included).
  bool WaitUntil(Mutex* mu, std::chrono::steady_clock::time_point deadline)
      REQUIRES(mu) {
    std::unique_lock<std::mutex> lock(mu->mu_, std::adopt_lock);
    const bool signalled =
        cv_.wait_until(lock, deadline) == std::cv_status::no_timeout;
    lock.release();  // the caller still holds mu
    return signalled;
  }
  // Wakes one waiter, if any.
  void Signal() { cv_.notify_one(); }
  // Wakes every waiter.
  void SignalAll() { cv_.notify_all(); }

 private:
  std::condition_variable cv_;
};

// A reader-writer mutex: one writer, or any number of readers.
class CAPABILITY("shared mutex") SharedMutex {
 public:
  SharedMutex() = default;
  SharedMutex(const SharedMutex&) = delete;
  SharedMutex& operator=(const SharedMutex&) = delete;

  // Blocks until this thread holds the mutex exclusively.
  void Lock() ACQUIRE() { mu_.lock(); }
  // Releases the exclusive hold.
  void Unlock() RELEASE() { mu_.unlock(); }
  // Blocks until this thread holds the mutex shared with other readers.
  void ReaderLock() ACQUIRE_SHARED() { mu_.lock_shared(); }
  // Releases the shared hold.
  void ReaderUnlock() RELEASE_SHARED() { mu_.unlock_shared(); }

 private:
  std::shared_mutex mu_;
};

// Holds a SharedMutex exclusively for its lifetime.
class SCOPED_CAPABILITY WriterMutexLock {
 public:
  // Blocks until `mu` is held exclusively; `mu` must outlive the lock.
  explicit WriterMutexLock(SharedMutex* mu) ACQUIRE(mu) : mu_(mu) {
    mu_->Lock();
  }
  // Releases the mutex.
  ~WriterMutexLock() RELEASE() { mu_->Unlock(); }

  WriterMutexLock(const WriterMutexLock&) = delete;
  WriterMutexLock& operator=(const WriterMutexLock&) = delete;

 private:
  SharedMutex* const mu_;
};

// Holds a SharedMutex shared for its lifetime.
class SCOPED_CAPABILITY ReaderMutexLock {
 public:
  // Blocks until `mu` is held shared; `mu` must outlive the lock.
  explicit ReaderMutexLock(SharedMutex* mu) ACQUIRE_SHARED(mu) : mu_(mu) {
    mu_->ReaderLock();
  }
  // Releases the shared hold.
  ~ReaderMutexLock() RELEASE() { mu_->ReaderUnlock(); }

  ReaderMutexLock(const ReaderMutexLock&) = delete;
  ReaderMutexLock& operator=(const ReaderMutexLock&) = delete;

 private:
  SharedMutex* const mu_;
};

}  // namespace locator

#endif  // LOCATOR_COMMON_MUTEX_H_
