// SnapshotSlot<T>: publishes immutable snapshots (std::shared_ptr<const T>)
// to many concurrent readers, like LevelDB's current Version.
//
// A writer Publish()es under a mutex and bumps a version. A reader's Get()
// checks that version with one acquire load against a thread-local cached
// copy of the shared_ptr, and only on a change takes the mutex to refresh
// it; so the read path costs no atomic read-modify-write and no lock in
// steady state, and readers never wait for a writer for longer than a
// pointer copy. (std::atomic<std::shared_ptr> in libstdc++ 12 costs three
// RMWs per load and releases its lock bit with relaxed order, which
// ThreadSanitizer rightly cannot see as synchronisation.)
//
// The snapshot a thread last read stays alive until that thread reads a
// newer one (or any other slot of the same T), or exits: memory for at
// most one stale snapshot per reader thread.
//
// Thread-safety: all methods may be called concurrently.

#ifndef LOCATOR_CORE_SNAPSHOT_SLOT_H_
#define LOCATOR_CORE_SNAPSHOT_SLOT_H_

#include <atomic>
#include <cstdint>
#include <memory>

#include "common/mutex.h"

namespace locator {

namespace internal {
// A process-wide unique id per slot, so that a thread-local cache can never
// mistake a new slot for a destroyed one at the same address.
inline uint64_t NextSnapshotSlotId() {
  static std::atomic<uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace internal

template <class T>
class SnapshotSlot {
 public:
  SnapshotSlot() : id_(internal::NextSnapshotSlotId()) {}
  SnapshotSlot(const SnapshotSlot&) = delete;
  SnapshotSlot& operator=(const SnapshotSlot&) = delete;

  // Makes `snapshot` the one readers see from now on.
  void Publish(std::shared_ptr<const T> snapshot) EXCLUDES(mu_) {
    MutexLock lock(&mu_);
    current_ = std::move(snapshot);
    version_.store(version_.load(std::memory_order_relaxed) + 1,
                   std::memory_order_release);
  }

  // The current snapshot, as an owning pointer (slow path: takes the lock).
  std::shared_ptr<const T> Current() const EXCLUDES(mu_) {
    MutexLock lock(&mu_);
    return current_;
  }

  // The current snapshot (null if none was published). The pointer stays
  // valid until this thread's next Get() on a SnapshotSlot<T>.
  const T* Get() const EXCLUDES(mu_) {
    thread_local Cache cache;
    const uint64_t version = version_.load(std::memory_order_acquire);
    if (cache.slot_id != id_ || cache.version != version) {
      MutexLock lock(&mu_);
      cache.snapshot = current_;
      cache.version = version_.load(std::memory_order_relaxed);
      cache.slot_id = id_;
    }
    return cache.snapshot.get();
  }

 private:
  struct Cache {
    uint64_t slot_id = 0;
    uint64_t version = 0;
    std::shared_ptr<const T> snapshot;
  };

  const uint64_t id_;
  mutable Mutex mu_;
  std::shared_ptr<const T> current_ GUARDED_BY(mu_);
  std::atomic<uint64_t> version_{0};
};

}  // namespace locator

#endif  // LOCATOR_CORE_SNAPSHOT_SLOT_H_
