// ProgressLine: while a load run goes on, rewrites one line of the terminal
// ("\r") once a second with the last second's call rate, latency and
// failures. Does nothing when stdout is not a terminal, so redirected
// output holds only the report.
//
// Owns the thread that prints. Thread-safety: construct and destroy on one
// thread; the printing thread only reads the recorder's intervals.

#ifndef LOCATOR_CLIENT_LOAD_PROGRESS_LINE_H_
#define LOCATOR_CLIENT_LOAD_PROGRESS_LINE_H_

#include <thread>

#include "client/load/run_recorder.h"

namespace locator {

class ProgressLine {
 public:
  // Starts printing if stdout is a terminal.
  explicit ProgressLine(RunRecorder& recorder);
  // Stops printing and clears the line.
  ~ProgressLine();

  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

 private:
  void PrintEverySecond(std::stop_token stop);

  RunRecorder& recorder_;
  std::jthread printer_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_PROGRESS_LINE_H_
