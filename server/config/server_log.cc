#include "server/config/server_log.h"

#include <atomic>
#include <iostream>

namespace locator {
namespace {

std::atomic<LogLevel> log_level{LogLevel::kInfo};

}  // namespace

const std::vector<std::pair<std::string, LogLevel>>& LogLevelWords() {
  static const std::vector<std::pair<std::string, LogLevel>> kWords = {
      {"error", LogLevel::kError},
      {"warning", LogLevel::kWarning},
      {"info", LogLevel::kInfo},
      {"debug", LogLevel::kDebug}};
  return kWords;
}

void SetLogLevel(LogLevel level) {
  log_level.store(level, std::memory_order_relaxed);
}

bool LogEnabled(LogLevel level) {
  return level <= log_level.load(std::memory_order_relaxed);
}

LogLine::LogLine(LogLevel level, std::string_view tag) {
  if (!LogEnabled(level)) return;
  line_.emplace();
  *line_ << "locatord ";
  if (level == LogLevel::kError) *line_ << "error: ";
  if (level == LogLevel::kWarning) *line_ << "warning: ";
  if (!tag.empty()) *line_ << '[' << tag << "] ";
}

LogLine::~LogLine() {
  if (line_.has_value()) std::cerr << line_->str() << std::endl;
}

}  // namespace locator
