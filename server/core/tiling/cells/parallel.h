// Parallel loops for the tiled build: plain threads started per call (a
// build runs a handful of phases, each long enough to pay for them).
//
// Thread-safety: the bodies run concurrently; they must only write what
// their own index or range owns.

#ifndef LOCATOR_CORE_TILING_PARALLEL_H_
#define LOCATOR_CORE_TILING_PARALLEL_H_

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace locator {

// Calls body(begin, end, slice) for `threads` contiguous slices of [0, n)
// (fewer when n is small), the first on the calling thread; returns when
// all are done.
template <class Body>
void ParallelSlices(size_t n, unsigned threads, const Body& body) {
  const size_t slices = std::clamp<size_t>(threads, 1, std::max<size_t>(n, 1));
  const auto bound = [&](size_t k) { return n * k / slices; };
  std::vector<std::thread> workers;
  for (size_t k = 1; k < slices; ++k) {
    workers.emplace_back([&, k] { body(bound(k), bound(k + 1), k); });
  }
  body(bound(0), bound(1), size_t{0});
  for (std::thread& worker : workers) worker.join();
}

// Calls task(i, worker) once for every i in [0, count) on `threads`
// threads, each taking the next i as it becomes free (worker is the
// thread's number, 0 for the calling thread); returns when all are done.
template <class Task>
void ParallelTasks(size_t count, unsigned threads, const Task& task) {
  std::atomic<size_t> next{0};
  ParallelSlices(std::min<size_t>(threads, count), threads,
                 [&](size_t, size_t, size_t worker) {
                   for (size_t i; (i = next.fetch_add(1)) < count;) {
                     task(i, worker);
                   }
                 });
}

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_PARALLEL_H_
