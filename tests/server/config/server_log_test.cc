// LogLine: a line below the configured level writes nothing; warnings and
// errors say so before the tag.

#include "server/config/server_log.h"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>

namespace locator {
namespace {

// Captures what std::cerr receives while it lives; restores the level.
class CapturedLog {
 public:
  CapturedLog() : previous_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CapturedLog() {
    std::cerr.rdbuf(previous_);
    SetLogLevel(LogLevel::kInfo);
  }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::streambuf* const previous_;
};

// Counts its evaluations when written to a stream.
struct Counted {
  int* count;
};
std::ostream& operator<<(std::ostream& out, const Counted& counted) {
  ++*counted.count;
  return out << "counted";
}

TEST(ServerLogTest, LinesBelowTheLevelWriteNothing) {
  CapturedLog log;
  SetLogLevel(LogLevel::kWarning);
  int formatted = 0;
  LogLine(LogLevel::kInfo, "terrain") << "info " << Counted{&formatted};
  LogLine(LogLevel::kDebug) << "debug " << Counted{&formatted};
  EXPECT_EQ(log.text(), "");
  EXPECT_EQ(formatted, 0) << "a filtered line formatted its operands";
  EXPECT_FALSE(LogEnabled(LogLevel::kInfo));
  EXPECT_TRUE(LogEnabled(LogLevel::kWarning));
  LogLine(LogLevel::kWarning, "terrain") << "a warning";
  LogLine(LogLevel::kError) << "an error";
  EXPECT_EQ(log.text(),
            "locatord warning: [terrain] a warning\n"
            "locatord error: an error\n");
}

TEST(ServerLogTest, InfoIsTheDefaultAndDebugShowsEverything) {
  CapturedLog log;
  LogLine(LogLevel::kInfo, "t") << "started";
  LogLine(LogLevel::kDebug) << "hidden";
  SetLogLevel(LogLevel::kDebug);
  LogLine(LogLevel::kDebug) << "shown";
  EXPECT_EQ(log.text(), "locatord [t] started\nlocatord shown\n");
}

TEST(ServerLogTest, ErrorLevelKeepsOnlyErrors) {
  CapturedLog log;
  SetLogLevel(LogLevel::kError);
  LogLine(LogLevel::kWarning) << "dropped";
  LogLine(LogLevel::kError) << "kept";
  EXPECT_EQ(log.text(), "locatord error: kept\n");
}

}  // namespace
}  // namespace locator
