#include "tests/server/main/hostile/hostile_expect.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <utility>

#include "common/grpc_code_name.h"

namespace locator::test {

Expectation& Expectation::Allow(grpc::StatusCode code,
                                std::vector<std::string> names) {
  refusals_.push_back({code, std::move(names)});
  return *this;
}

Expectation& Expectation::Require(grpc::StatusCode code,
                                  std::vector<std::string> names) {
  ok_allowed_ = false;
  return Allow(code, std::move(names));
}

Expectation& Expectation::AllowHttpStatus(unsigned status) {
  http_statuses_.push_back(status);
  return *this;
}

bool Expectation::Accepts(grpc::StatusCode code) const {
  return std::any_of(refusals_.begin(), refusals_.end(),
                     [code](const Refusal& r) { return r.code == code; });
}

std::string Expectation::Judge(const Outcome& outcome) const {
  if (std::find(http_statuses_.begin(), http_statuses_.end(),
                outcome.http_status) != http_statuses_.end()) {
    return "";
  }
  if (!outcome.transport_problem.empty()) return outcome.transport_problem;
  if (outcome.code == grpc::StatusCode::OK) {
    return ok_allowed_ ? "" : "answered OK, want " + Describe();
  }
  const std::string got =
      CodeName(outcome.code) + " \"" + Shorten(outcome.message) + "\"";
  if (!Accepts(outcome.code)) return "got " + got + ", want " + Describe();
  if (outcome.message.empty()) return "got " + got + " with no message";
  if (outcome.message.size() > kMaxMessageBytes) {
    return "got " + got + ": a message of " +
           std::to_string(outcome.message.size()) + " bytes (at most " +
           std::to_string(kMaxMessageBytes) + ")";
  }
  const std::string& m = outcome.message;
  size_t digits = 0;
  for (size_t i = 0; i + 1 < m.size(); ++i) {
    const auto is_digit = [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0;
    };
    if (m[i] == '.' && is_digit(m[i + 1]) && digits > kMaxDigitRun) {
      return "got " + got + ": a number of more than " +
             std::to_string(kMaxDigitRun) + " digits in the message";
    }
    digits = is_digit(m[i]) ? digits + 1 : 0;
  }
  for (const Refusal& refusal : refusals_) {
    if (refusal.code != outcome.code) continue;
    for (const std::string& name : refusal.names) {
      if (Names(outcome.message, name)) return "";
    }
  }
  return "got " + got + ", whose message names none of the fields: want " +
         Describe();
}

std::string Expectation::Describe() const {
  std::string text = ok_allowed_ ? "OK" : "";
  for (const Refusal& refusal : refusals_) {
    if (!text.empty()) text += ", or ";
    text += CodeName(refusal.code) + " naming ";
    for (size_t i = 0; i < refusal.names.size(); ++i) {
      text += (i == 0 ? "" : "|") + refusal.names[i];
    }
  }
  for (unsigned status : http_statuses_) {
    text += ", or HTTP " + std::to_string(status);
  }
  return text;
}

std::string CodeName(grpc::StatusCode code) {
  return std::string(GrpcCodeName(code));
}

std::string Shorten(const std::string& text, size_t limit) {
  std::string shown;
  for (size_t i = 0; i < text.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      shown += static_cast<char>(c);
    } else {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", c);
      shown += escape;
    }
  }
  if (text.size() <= limit) return shown;
  return shown + "... (" + std::to_string(text.size()) + " bytes)";
}

bool Names(const std::string& text, const std::string& word) {
  const auto equal = [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  };
  return std::search(text.begin(), text.end(), word.begin(), word.end(),
                     equal) != text.end();
}

}  // namespace locator::test
