#include "tests/server/http/prometheus_text.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <set>

namespace locator::test {
namespace {

bool IsNameStart(char c, bool colon_ok) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         (colon_ok && c == ':');
}

bool IsNameChar(char c, bool colon_ok) {
  return IsNameStart(c, colon_ok) || (c >= '0' && c <= '9');
}

// Reads a metric name (colons allowed) or label name from the front of
// `line`.
bool TakeName(std::string_view* line, bool colon_ok, std::string* name) {
  size_t n = 0;
  if (line->empty() || !IsNameStart((*line)[0], colon_ok)) return false;
  while (n < line->size() && IsNameChar((*line)[n], colon_ok)) ++n;
  *name = std::string(line->substr(0, n));
  line->remove_prefix(n);
  return true;
}

bool IsMetricName(std::string_view text) {
  std::string name;
  return TakeName(&text, true, &name) && text.empty();
}

bool ParseValue(std::string_view text, double* value) {
  if (text == "+Inf") {
    *value = std::numeric_limits<double>::infinity();
  } else if (text == "-Inf") {
    *value = -std::numeric_limits<double>::infinity();
  } else if (text == "NaN") {
    *value = std::numeric_limits<double>::quiet_NaN();
  } else {
    const auto [end, error] =
        std::from_chars(text.data(), text.data() + text.size(), *value);
    return !text.empty() && error == std::errc() &&
           end == text.data() + text.size() && std::isfinite(*value);
  }
  return true;
}

// Reads '"value"' with the escapes \\, \" and \n.
bool TakeLabelValue(std::string_view* line, std::string* value) {
  if (line->empty() || (*line)[0] != '"') return false;
  size_t i = 1;
  value->clear();
  for (; i < line->size() && (*line)[i] != '"'; ++i) {
    if ((*line)[i] != '\\') {
      *value += (*line)[i];
      continue;
    }
    if (++i == line->size()) return false;
    switch ((*line)[i]) {
      case '\\':
        *value += '\\';
        break;
      case '"':
        *value += '"';
        break;
      case 'n':
        *value += '\n';
        break;
      default:
        return false;
    }
  }
  if (i == line->size()) return false;
  line->remove_prefix(i + 1);
  return true;
}

bool TakeLabels(std::string_view* line,
                std::map<std::string, std::string>* labels) {
  if (line->empty() || (*line)[0] != '{') return true;
  line->remove_prefix(1);
  if (!line->empty() && (*line)[0] == '}') {
    line->remove_prefix(1);
    return true;
  }
  for (;;) {
    std::string name, value;
    if (!TakeName(line, false, &name) || line->empty() || (*line)[0] != '=') {
      return false;
    }
    line->remove_prefix(1);
    if (!TakeLabelValue(line, &value)) return false;
    if (!labels->emplace(name, value).second) return false;
    if (line->empty()) return false;
    const char next = (*line)[0];
    line->remove_prefix(1);
    if (next == '}') return true;
    if (next != ',') return false;
  }
}

// The declared family a sample named `name` belongs to, or "".
std::string FamilyOf(const std::map<std::string, std::string>& types,
                     const std::string& name, bool has_le) {
  if (types.count(name) > 0) return name;
  for (std::string_view suffix : {"_bucket", "_sum", "_count"}) {
    if (name.size() <= suffix.size() ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
      continue;
    }
    const std::string base = name.substr(0, name.size() - suffix.size());
    const auto type = types.find(base);
    if (type == types.end()) continue;
    if (type->second == "histogram" && (suffix != "_bucket" || has_le)) {
      return base;
    }
    if (type->second == "summary" && suffix != "_bucket") return base;
  }
  return "";
}

}  // namespace

std::optional<double> PrometheusText::Value(
    std::string_view name,
    const std::map<std::string, std::string>& labels) const {
  std::optional<double> found;
  for (const PrometheusSample& sample : samples) {
    if (sample.name != name) continue;
    bool match = true;
    for (const auto& [key, value] : labels) {
      const auto it = sample.labels.find(key);
      match = match && it != sample.labels.end() && it->second == value;
    }
    if (!match) continue;
    if (found) return std::nullopt;
    found = sample.value;
  }
  return found;
}

Status ParsePrometheusText(std::string_view text, PrometheusText* out) {
  static const std::set<std::string, std::less<>> kTypes = {
      "counter", "gauge", "histogram", "summary", "untyped"};
  std::set<std::string> sampled_families;
  size_t line_number = 0;
  if (!text.empty() && text.back() != '\n') {
    return Status::InvalidArgument("the last line does not end in \\n");
  }
  while (!text.empty()) {
    ++line_number;
    const size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end + 1);
    const auto bad = [&](std::string_view why) {
      return Status::InvalidArgument("line " + std::to_string(line_number) +
                                     " (" + std::string(why) +
                                     "): " + std::string(line));
    };
    if (line.empty()) continue;
    if (line.starts_with("# HELP ") || line.starts_with("# TYPE ")) {
      const bool is_type = line[2] == 'T';
      std::string_view rest = line.substr(7);
      std::string name;
      if (!TakeName(&rest, true, &name) || !rest.starts_with(' ')) {
        return bad("bad metric name");
      }
      rest.remove_prefix(1);
      if (!is_type) continue;
      if (kTypes.count(rest) == 0) return bad("unknown type");
      if (sampled_families.count(name) > 0) return bad("TYPE after samples");
      if (!out->types.emplace(name, std::string(rest)).second) {
        return bad("TYPE twice");
      }
      continue;
    }
    if (line[0] == '#') continue;  // any other comment
    PrometheusSample sample;
    if (!TakeName(&line, true, &sample.name)) return bad("bad metric name");
    if (!TakeLabels(&line, &sample.labels)) return bad("bad labels");
    if (!line.starts_with(' ')) return bad("no value");
    line.remove_prefix(1);
    const size_t space = line.find(' ');
    if (!ParseValue(line.substr(0, space), &sample.value)) {
      return bad("bad value");
    }
    if (space != std::string_view::npos) {
      const std::string_view stamp = line.substr(space + 1);
      int64_t ms = 0;
      const auto [at, error] =
          std::from_chars(stamp.data(), stamp.data() + stamp.size(), ms);
      if (error != std::errc() || at != stamp.data() + stamp.size()) {
        return bad("bad timestamp");
      }
    }
    const std::string family =
        FamilyOf(out->types, sample.name, sample.labels.count("le") > 0);
    if (family.empty()) return bad("sample of an undeclared family");
    if (!IsMetricName(family)) return bad("bad family name");
    sampled_families.insert(family);
    out->samples.push_back(std::move(sample));
  }
  return Status::OK();
}

}  // namespace locator::test
