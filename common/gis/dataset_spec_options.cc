#include "common/gis/dataset_spec_options.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

constexpr std::string_view kSimplifyOptionNames = "max_error, max_points";
// A TIN needs three vertices; mesh ids are 32-bit.
constexpr uint64_t kMinMaxPoints = 3;
constexpr uint64_t kMaxMaxPoints = std::numeric_limits<uint32_t>::max();

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Decodes the %XX escapes of one value; false on a malformed escape.
bool PercentDecode(std::string_view in, std::string* out) {
  out->clear();
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '%') {
      *out += in[i];
      continue;
    }
    if (i + 2 >= in.size()) return false;
    const int high = HexDigit(in[i + 1]);
    const int low = HexDigit(in[i + 2]);
    if (high < 0 || low < 0) return false;
    *out += static_cast<char>(high * 16 + low);
    i += 2;
  }
  return true;
}

}  // namespace

Status SpecError(std::string_view spec, std::string_view what) {
  return Status::InvalidArgument("dataset spec " + QuotedInput(spec) + ": " +
                                 std::string(what));
}

SpecParts SplitSpec(std::string_view spec, std::string_view prefix) {
  SpecParts parts;
  parts.source = spec;
  if (!prefix.empty() && spec.starts_with(prefix)) {
    parts.prefix = spec.substr(0, prefix.size());
    parts.source.remove_prefix(prefix.size());
  }
  if (const size_t query = parts.source.find('?');
      query != std::string_view::npos) {
    parts.options = parts.source.substr(query);
    parts.source = parts.source.substr(0, query);
  }
  return parts;
}

bool SourceHasExtension(std::string_view spec,
                        std::span<const std::string_view> extensions) {
  const std::string_view source = SplitSpec(spec).source;
  for (std::string_view extension : extensions) {
    if (source.size() < extension.size()) continue;
    const std::string_view tail =
        source.substr(source.size() - extension.size());
    bool same = true;
    for (size_t i = 0; i < tail.size() && same; ++i) {
      same = std::tolower(static_cast<unsigned char>(tail[i])) == extension[i];
    }
    if (same) return true;
  }
  return false;
}

Status ParseSpecOptions(std::string_view spec, std::vector<SpecOption>* out) {
  out->clear();
  std::string_view options = SplitSpec(spec).options;
  if (!options.empty()) options.remove_prefix(1);  // the '?'
  while (!options.empty()) {
    const size_t amp = options.find('&');
    const std::string_view text = options.substr(0, amp);
    options = amp == std::string_view::npos ? std::string_view()
                                            : options.substr(amp + 1);
    if (text.empty()) continue;
    const size_t eq = text.find('=');
    if (eq == std::string_view::npos) {
      return SpecError(spec,
                       "option " + QuotedInput(text) + " has no '=VALUE'");
    }
    SpecOption option;
    option.name = std::string(text.substr(0, eq));
    option.text = text;
    if (!PercentDecode(text.substr(eq + 1), &option.value)) {
      return SpecError(spec, "option " + QuotedInput(option.name) +
                                 " has a malformed %-escape");
    }
    out->push_back(std::move(option));
  }
  return Status::OK();
}

Status BadSpecOption(std::string_view spec, std::string_view name,
                     std::string_view value, std::string_view expected) {
  return SpecError(spec, "option " + QuotedInput(name) + " must be " +
                             std::string(expected) + ", got " +
                             QuotedInput(value));
}

Status UnknownSpecOption(std::string_view spec, std::string_view name,
                         std::string_view known) {
  std::string list(known);
  if (!list.empty()) list += ", ";
  list += kSimplifyOptionNames;
  return SpecError(
      spec, "unknown option " + QuotedInput(name) + " (known: " + list + ")");
}

Status SpecOptionDouble(std::string_view spec, const SpecOption& option,
                        double min, double* out) {
  const std::string& text = option.value;
  double value = 0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() ||
      end != text.data() + text.size() || !std::isfinite(value) ||
      value < min) {
    return BadSpecOption(
        spec, option.name, text,
        "a finite number >= " + std::to_string(static_cast<long long>(min)));
  }
  *out = value;
  return Status::OK();
}

Status SpecOptionInteger(std::string_view spec, const SpecOption& option,
                         uint64_t min, uint64_t max, uint64_t* out) {
  const std::string& text = option.value;
  uint64_t value = 0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() ||
      end != text.data() + text.size() || value < min || value > max) {
    return BadSpecOption(spec, option.name, text,
                         "an integer from " + std::to_string(min) + " to " +
                             std::to_string(max));
  }
  *out = value;
  return Status::OK();
}

Status TakeSimplifyOptions(std::string_view spec, SimplifySpec* simplify,
                           std::string* rest) {
  std::vector<SpecOption> options;
  RETURN_IF_ERROR(ParseSpecOptions(spec, &options));
  SimplifySpec parsed;
  bool have_error = false;
  bool have_points = false;
  std::string kept;
  for (const SpecOption& option : options) {
    bool* seen = option.name == "max_error"    ? &have_error
                 : option.name == "max_points" ? &have_points
                                               : nullptr;
    if (seen == nullptr) {
      if (!kept.empty()) kept += '&';
      kept.append(option.text);
      continue;
    }
    if (*seen) {
      return SpecError(spec,
                       "option " + QuotedInput(option.name) + " given twice");
    }
    *seen = true;
    const Status status =
        option.name == "max_error"
            ? SpecOptionDouble(spec, option, 0, &parsed.max_error)
            : SpecOptionInteger(spec, option, kMinMaxPoints, kMaxMaxPoints,
                                &parsed.max_points);
    if (!status.ok()) return status;
  }
  parsed.requested = have_error || have_points;
  *rest = std::string(SplitSpec(spec).source);
  if (!kept.empty()) *rest += "?" + kept;
  *simplify = parsed;
  return Status::OK();
}

}  // namespace locator::gis
