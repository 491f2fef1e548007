// LogLine: one line of locatord's log on stderr, "locatord [TAG] message",
// written whole when the statement ends, if its level passes the process's
// log level (locatord --log-level; SetLogLevel). Warnings and errors say so
// first ("locatord warning: [TAG] message"). The tag names the dataset a
// line is about when the server holds several (empty: no tag).
//
//   LogLine(LogLevel::kInfo, tag) << "loaded " << n << " points";
//
// A filtered line formats nothing: it costs a relaxed atomic load and the
// evaluation of its operands.
//
// Thread-safety: the level is a relaxed atomic, so a change is seen by
// every thread soon, in no particular order with other memory; each line is
// one write of std::cerr, so lines from several threads do not interleave
// within a line.

#ifndef LOCATOR_SERVER_SERVER_LOG_H_
#define LOCATOR_SERVER_SERVER_LOG_H_

#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace locator {

// The more severe, the smaller: a line passes when its level <= the
// process's.
enum class LogLevel { kError, kWarning, kInfo, kDebug };

// The words of --log-level, most severe first: error, warning, info, debug.
const std::vector<std::pair<std::string, LogLevel>>& LogLevelWords();

// Lines of `level` and more severe are written from now on (default kInfo).
void SetLogLevel(LogLevel level);

// Whether a line of `level` is written.
bool LogEnabled(LogLevel level);

class LogLine {
 public:
  explicit LogLine(LogLevel level, std::string_view tag = {});
  // Writes the line, when its level passes.
  ~LogLine();

  LogLine(const LogLine&) = delete;
  LogLine& operator=(const LogLine&) = delete;

  template <typename T>
  LogLine& operator<<(const T& value) {
    if (line_.has_value()) *line_ << value;
    return *this;
  }

 private:
  // Empty when the level is filtered out.
  std::optional<std::ostringstream> line_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_SERVER_LOG_H_
