// BuildHeartbeat: a line every interval saying the phase, with the
// simplifier's last progress while simplifying, reported from another
// thread. (The concurrency label runs it under ThreadSanitizer too.)

#include "server/datasets/build_heartbeat.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "common/mutex.h"
#include "tests/testing/wait.h"

namespace locator {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr auto kInterval = std::chrono::milliseconds(5);

// Collects the heartbeat's lines; WaitFor() waits (with a generous
// deadline) until one matches.
class Lines {
 public:
  BuildHeartbeat::Sink Sink() {
    return [this](const std::string& line) {
      MutexLock lock(&mu_);
      lines_.push_back(line);
      added_.SignalAll();
    };
  }
  // The first line from `from` on that contains `text`; "" at the deadline.
  std::string WaitFor(const std::string& text, size_t* from) {
    const auto deadline =
        std::chrono::steady_clock::now() + test::kGenerousWait;
    MutexLock lock(&mu_);
    while (true) {
      for (; *from < lines_.size(); ++*from) {
        if (lines_[*from].find(text) != std::string::npos) return lines_[*from];
      }
      if (!added_.WaitUntil(&mu_, deadline) &&
          std::chrono::steady_clock::now() >= deadline) {
        return "";
      }
    }
  }

 private:
  Mutex mu_;
  CondVar added_;
  std::vector<std::string> lines_ GUARDED_BY(mu_);
};

TEST(BuildHeartbeatTest, SaysThePhaseAndTheLatestProgressEveryInterval) {
  Lines lines;
  size_t seen = 0;
  {
    BuildHeartbeat heartbeat(lines.Sink(), kInterval);
    EXPECT_THAT(lines.WaitFor("loading for ", &seen),
                StartsWith("loading for "));
    // Reports come from the simplifier's threads.
    std::thread simplifier([&heartbeat] {
      heartbeat.Report({1200, 3.5, 0.5});
      heartbeat.Report({4800, 0.75, 1.0});
    });
    simplifier.join();
    EXPECT_THAT(lines.WaitFor("simplifying", &seen),
                HasSubstr(": 4800 vertices, largest error left 0.75"));
    heartbeat.SetPhase("building the serving mesh");
    const std::string mesh = lines.WaitFor("building the serving mesh", &seen);
    EXPECT_THAT(mesh, StartsWith("building the serving mesh for "));
    EXPECT_THAT(mesh, ::testing::Not(HasSubstr("vertices")));
  }
}

}  // namespace
}  // namespace locator
