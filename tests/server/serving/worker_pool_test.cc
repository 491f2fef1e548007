// WorkerPool: tasks run on the pool's threads, in FIFO order, and the
// destructor runs every task already queued before it joins (the first two
// tests destroy the pool right after queueing).

#include "server/serving/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace locator {
namespace {

TEST(WorkerPoolTest, RunsEveryTaskOnItsOwnThreads) {
  constexpr int kTasks = 1000;
  std::mutex mu;
  std::set<std::thread::id> ran_on;
  std::atomic<int> ran{0};
  {
    WorkerPool pool(3);
    EXPECT_EQ(pool.size(), 3u);
    for (int i = 0; i < kTasks; ++i) {
      pool.Submit([&] {
        std::lock_guard<std::mutex> lock(mu);
        ran_on.insert(std::this_thread::get_id());
        ++ran;
      });
    }
  }
  EXPECT_EQ(ran.load(), kTasks);
  EXPECT_LE(ran_on.size(), 3u);
  EXPECT_EQ(ran_on.count(std::this_thread::get_id()), 0u);
}

TEST(WorkerPoolTest, OneThreadRunsTasksInSubmissionOrder) {
  std::vector<int> order;
  {
    WorkerPool pool(1);
    for (int i = 0; i < 100; ++i)
      pool.Submit([&order, i] { order.push_back(i); });
  }
  ASSERT_EQ(order.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(order[i], i);
}

TEST(WorkerPoolTest, TaskMaySubmitAnotherTask) {
  std::promise<int> inner;
  std::future<int> inner_ran = inner.get_future();
  WorkerPool pool(2);
  pool.Submit([&] { pool.Submit([&] { inner.set_value(7); }); });
  EXPECT_EQ(inner_ran.get(), 7);
}

TEST(WorkerPoolTest, PoolWithoutThreadsHasSizeZero) {
  WorkerPool pool(0);
  EXPECT_EQ(pool.size(), 0u);
}

}  // namespace
}  // namespace locator
