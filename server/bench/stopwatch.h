// Stopwatch: wall-clock seconds since it was started, for the benchmark
// programs' timings.
//
// Thread-safety: a plain value.

#ifndef LOCATOR_SERVER_BENCH_STOPWATCH_H_
#define LOCATOR_SERVER_BENCH_STOPWATCH_H_

#include <chrono>

namespace locator::bench {

class Stopwatch {
 public:
  // Starts timing now.
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}

  // Seconds since construction or the last Restart().
  double Seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start_)
        .count();
  }
  // Starts timing again from now.
  void Restart() { start_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_STOPWATCH_H_
