#include "client/load/progress_line.h"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>

#include "client/load/load_report.h"
#include "common/str_cat.h"

namespace locator {

ProgressLine::ProgressLine(RunRecorder& recorder) : recorder_(recorder) {
  if (isatty(STDOUT_FILENO)) {
    printer_ =
        std::jthread([this](std::stop_token stop) { PrintEverySecond(stop); });
  }
}

ProgressLine::~ProgressLine() {
  if (!printer_.joinable()) return;
  printer_.request_stop();
  printer_.join();
  std::fputs("\r\033[K", stdout);  // erase the line for the report
  std::fflush(stdout);
}

void ProgressLine::PrintEverySecond(std::stop_token stop) {
  std::mutex mutex;
  std::condition_variable_any tick;
  std::unique_lock<std::mutex> lock(mutex);
  for (int seconds = 1;; ++seconds) {
    // Returns early, with stop requested, when the run ends.
    tick.wait_for(lock, stop, std::chrono::seconds(1), [] { return false; });
    if (stop.stop_requested()) return;
    const RunInterval interval = recorder_.TakeInterval();
    const std::string line =
        StrCat({"\r\033[K", std::to_string(seconds),
                " s: ", std::to_string(interval.calls), " calls/s, p50 ",
                FormatMicros(interval.latency.Percentile(50)), ", p99 ",
                FormatMicros(interval.latency.Percentile(99)), ", ",
                std::to_string(interval.failed_calls), " failed"});
    std::fputs(line.c_str(), stdout);
    std::fflush(stdout);
  }
}

}  // namespace locator
