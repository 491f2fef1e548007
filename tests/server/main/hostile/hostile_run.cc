#include "tests/server/main/hostile/hostile_run.h"

#include <utility>

namespace locator::test {
namespace {

std::string MiB(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

HostileRun::HostileRun(HostileServer* server, std::string family, uint64_t seed)
    : server_(server), family_(std::move(family)), seed_(seed) {
  ResetMemoryBaseline();
}

HostileRun::~HostileRun() {
  if (!stopped_) Control();
  std::printf(
      "%s: %zu hostile calls, %zu OK answers checked, %zu failed, %d "
      "restarts (seed %llu)\n",
      family_.c_str(), calls_, answers_, failures_, restarts_,
      static_cast<unsigned long long>(seed_));
  if (failures_ > static_cast<size_t>(kMaxReported)) {
    ADD_FAILURE() << family_ << ": " << failures_ << " problems in all, "
                  << kMaxReported << " shown (seed " << seed_
                  << "; LOCATOR_HOSTILE_SEED reproduces it)";
  }
}

void HostileRun::Fail(const std::string& message) {
  if (++failures_ > static_cast<size_t>(kMaxReported)) return;
  ADD_FAILURE() << family_ << " (seed " << seed_ << "): " << message;
}

void HostileRun::Record(size_t index, const std::string& what,
                        const Outcome& outcome, const std::string& problem) {
  ++calls_;
  hung_ = hung_ || OutlivedDeadline(outcome);
  const std::string call = "case " + std::to_string(index) + ": " + what;
  const std::string touched = server_->TouchedOutside();
  if (!problem.empty() || !touched.empty()) {
    Fail(call + "\n  " + (problem.empty() ? touched : problem));
  }
  batch_.push_back(call);
  // After a failed call at once: if it crashed or hung the server, the
  // control names it as the batch's last call, and the restart keeps the
  // calls after it from failing for its sake.
  if (!problem.empty() || !touched.empty() ||
      batch_.size() >= static_cast<size_t>(kCallsPerControl)) {
    Control();
  }
}

void HostileRun::Control() {
  std::string problem = server_->Control();
  const bool down = !problem.empty() || hung_;
  hung_ = false;
  if (!down && rss_baseline_) {
    const std::optional<uint64_t> rss = server_->ResidentBytes();
    const std::optional<uint64_t> peak = server_->PeakResidentBytes();
    if (rss && *rss > *rss_baseline_ + kRssGrowth) {
      problem = "resident memory " + MiB(*rss) + ", " + MiB(*rss_baseline_) +
                " before: more than " + MiB(kRssGrowth) + " kept";
      rss_baseline_ = rss;  // report each growth once
    } else if (peak && *peak > *rss_baseline_ + kPeakGrowth) {
      problem = "peak resident memory " + MiB(*peak) + ", " +
                MiB(*rss_baseline_) + " before: more than " + MiB(kPeakGrowth) +
                " used at once";
      rss_baseline_ = *peak;  // report each peak once
    }
  }
  if (!problem.empty()) {
    std::string calls;
    for (const std::string& call : batch_) calls += "\n    " + Shorten(call);
    Fail("after the calls" + calls + "\n  " + problem);
  }
  batch_.clear();
  if (!down) return;
  // Reported whatever the count: the calls not made are no coverage.
  if (++restarts_ > kMaxRestarts) {
    ADD_FAILURE() << family_ << ": stopping after " << calls_
                  << " calls: the server was restarted " << kMaxRestarts
                  << " times";
    stopped_ = true;
    return;
  }
  if (const Status restarted = server_->Restart(); !restarted.ok()) {
    ADD_FAILURE() << family_ << ": stopping after " << calls_
                  << " calls: cannot restart the server: "
                  << restarted.ToString();
    stopped_ = true;
    return;
  }
  ResetMemoryBaseline();
}

void HostileRun::ResetMemoryBaseline() {
  rss_baseline_ = server_->ResidentBytes();
}

std::vector<Transport> CaseTransports(size_t index) {
#if defined(LOCATOR_SANITIZED_SERVER)
  return {index % 2 == 0 ? Transport::kGrpc : Transport::kHttp};
#else
  (void)index;
  return {Transport::kGrpc, Transport::kHttp};
#endif
}

HostileServer* HostileTest::server_ = nullptr;

void HostileTest::SetUpTestSuite() {
  server_ = HostileServer::Create().release();
}

void HostileTest::TearDownTestSuite() {
  delete server_;
  server_ = nullptr;
}

void HostileTest::SetUp() {
  ASSERT_NE(server_, nullptr);
  if (!server_->Control().empty()) {
    const Status restarted = server_->Restart();
    ASSERT_TRUE(restarted.ok()) << restarted.ToString();
  }
  std::printf(
      "seed %llu, %d repeats (LOCATOR_HOSTILE_SEED, "
      "LOCATOR_HOSTILE_REPEATS)\n",
      static_cast<unsigned long long>(seed()), HostileRepeats());
}

}  // namespace locator::test
