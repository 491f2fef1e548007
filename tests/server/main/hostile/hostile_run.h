// HostileRun: one property run of the hostile-input test over one family
// of calls, against a HostileServer.
//
// Every call's problem ("" for none) is recorded with its case index and
// summary; the first kMaxReported become test failures, each naming the
// seed and the case, and the rest are counted. After every failed call,
// every kCallsPerControl calls and at the end, the control query runs: a server
// that exited, hangs or answers it wrong is a failure naming the calls of that
// batch, and is restarted (at most kMaxRestarts times; then the run stops) so
// that one hole does not hide the next. A call that outlived its deadline
// restarts the server too: the thread it may still hold would slow every
// later call. The control also checks the server's
// resident memory: at most kRssGrowth above what it was when the run (or
// the restarted server) began, and its peak at most kPeakGrowth above it
// (skipped under sanitizers). And after every call, nothing may have
// opened, read or written a file in the server's outside directory
// (HostileServer::TouchedOutside).
//
// HostileTest is the suite fixture: one HostileServer for every test in
// the process, restarted by SetUp() if a test left it down.
//
// Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_RUN_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_RUN_H_

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tests/server/main/hostile/hostile_expect.h"
#include "tests/server/main/hostile/hostile_server.h"

namespace locator::test {

class HostileRun {
 public:
  static constexpr int kCallsPerControl = 16;
  static constexpr int kMaxRestarts = 3;
  static constexpr int kMaxReported = 25;
  static constexpr uint64_t kRssGrowth = uint64_t{256} << 20;
  static constexpr uint64_t kPeakGrowth = uint64_t{1} << 30;

  HostileRun(HostileServer* server, std::string family, uint64_t seed);
  // Runs the last control and reports the counts.
  ~HostileRun();

  HostileRun(const HostileRun&) = delete;
  HostileRun& operator=(const HostileRun&) = delete;

  // Records call `what` of case `index`, how it ended and its `problem`
  // (none if empty); runs the control when a batch of calls is complete.
  void Record(size_t index, const std::string& what, const Outcome& outcome,
              const std::string& problem);
  // Counts an OK answer the run checked (printed at the end, so that a run
  // whose answers were all refusals shows).
  void Answered() { ++answers_; }
  // Whether the run had to stop (the server could not be kept up).
  bool stopped() const { return stopped_; }
  size_t calls() const { return calls_; }

  // The control query now, and a restart if it fails.
  void Control();

 private:
  void Fail(const std::string& message);
  void ResetMemoryBaseline();

  HostileServer* const server_;
  const std::string family_;
  const uint64_t seed_;
  std::vector<std::string> batch_;  // the calls since the last control
  size_t calls_ = 0;
  size_t answers_ = 0;
  size_t failures_ = 0;
  int restarts_ = 0;
  bool stopped_ = false;
  bool hung_ = false;  // a call since the last control outlived its deadline
  std::optional<uint64_t> rss_baseline_;
};

// The transports case `index` travels on: both, or, when the server runs
// under a sanitizer (every call several times slower), one, alternating
// from case to case, so that each transport still meets every kind of
// case.
std::vector<Transport> CaseTransports(size_t index);

class HostileTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite();
  static void TearDownTestSuite();
  void SetUp() override;

  static uint64_t seed() { return HostileSeed(); }

  static HostileServer* server_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_RUN_H_
