// LogLine: one line of locatord's log on stderr, "locatord [TAG] message",
// written whole when the statement ends. The tag names the dataset a line
// is about when the server holds several (empty: no tag).
//
// Thread-safety: each line is one write of std::cerr; lines from several
// threads do not interleave within a line.

#ifndef LOCATOR_SERVER_SERVER_LOG_H_
#define LOCATOR_SERVER_SERVER_LOG_H_

#include <iostream>
#include <sstream>
#include <string_view>

namespace locator {

class LogLine {
 public:
  explicit LogLine(std::string_view tag = {}) {
    line_ << "locatord ";
    if (!tag.empty()) line_ << '[' << tag << "] ";
  }
  ~LogLine() { std::cerr << line_.str() << std::endl; }

  LogLine(const LogLine&) = delete;
  LogLine& operator=(const LogLine&) = delete;

  template <typename T>
  LogLine& operator<<(const T& value) {
    line_ << value;
    return *this;
  }

 private:
  std::ostringstream line_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_SERVER_LOG_H_
