// WorkerPool: a fixed set of threads running submitted tasks in FIFO order.
//
// Owns its threads; they start in the constructor and are joined by the
// destructor, which first runs every task already submitted.
//
// Thread-safety: Submit() may be called from any thread, including from a
// task. Tasks must not block waiting for other tasks (the pool is small).

#ifndef LOCATOR_SERVER_WORKER_POOL_H_
#define LOCATOR_SERVER_WORKER_POOL_H_

#include <cstddef>
#include <deque>
#include <functional>
#include <thread>
#include <vector>

#include "common/mutex.h"

namespace locator {

class WorkerPool {
 public:
  // Starts `threads` worker threads. With none, submitted tasks never run:
  // callers check size() first.
  explicit WorkerPool(size_t threads);
  // Runs the queued tasks, then joins the threads.
  ~WorkerPool();

  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Queues `task` to run on one of the threads.
  void Submit(std::function<void()> task) EXCLUDES(mu_);

  size_t size() const { return threads_.size(); }

 private:
  void RunWorker() EXCLUDES(mu_);

  Mutex mu_;
  CondVar has_work_;
  std::deque<std::function<void()>> tasks_ GUARDED_BY(mu_);
  bool stopping_ GUARDED_BY(mu_) = false;
  std::vector<std::thread> threads_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_WORKER_POOL_H_
