// WorkerPool: a fixed set of threads running submitted tasks in FIFO order.
//
// Owns its threads; they start in the constructor and are joined by the
// destructor, which first runs every task already submitted.
//
// Thread-safety: Submit() may be called from any thread, including from a
// task. Tasks must not block waiting for other tasks (the pool is small).

#ifndef LOCATOR_SERVER_WORKER_POOL_H_
#define LOCATOR_SERVER_WORKER_POOL_H_

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

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
  void Submit(std::function<void()> task);

  size_t size() const { return threads_.size(); }

 private:
  void RunWorker();

  std::mutex mu_;
  std::condition_variable has_work_;
  std::deque<std::function<void()>> tasks_;  // guarded by mu_
  bool stopping_ = false;                    // guarded by mu_
  std::vector<std::thread> threads_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_WORKER_POOL_H_
