#include "common/flags/flag_value.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <sstream>

#include "common/flags/byte_size.h"

namespace locator {
namespace {

Status Problem(std::string_view problem) {
  return Status::InvalidArgument(std::string(problem));
}

// "from 1 to 256", or ">= 1" when max is as large as the type allows.
std::string RangeText(uint64_t min, uint64_t max, std::string_view unit) {
  std::ostringstream text;
  if (max >= static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) {
    text << ">= " << min;
    if (!unit.empty()) text << " " << unit;
  } else {
    text << "from " << min << " to " << max;
    if (!unit.empty()) text << " " << unit;
  }
  return text.str();
}

// The shortest text that reads back as `value` ("0.1", "2.5", "30").
std::string NumberText(double value) {
  char buffer[32];
  const auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string();
}

// "64MiB" for a whole number of MiB (or GiB, KiB), else the bytes.
std::string ByteText(uint64_t bytes) {
  constexpr std::pair<uint64_t, const char*> kUnits[] = {
      {uint64_t{1} << 30, "GiB"},
      {uint64_t{1} << 20, "MiB"},
      {uint64_t{1} << 10, "KiB"}};
  for (const auto& [scale, unit] : kUnits) {
    if (bytes != 0 && bytes % scale == 0) {
      return std::to_string(bytes / scale) + unit;
    }
  }
  return std::to_string(bytes);
}

// "a, b or c".
std::string Alternatives(const std::vector<std::string>& words) {
  std::string text;
  for (size_t i = 0; i < words.size(); ++i) {
    if (i > 0) text += i + 1 == words.size() ? " or " : ", ";
    text += words[i];
  }
  return text;
}

FlagValue NumberValue(double min, bool above, std::string_view unit,
                      std::string shape, std::string default_text,
                      std::function<void(double)> store) {
  std::string form = "must be a number";
  if (!unit.empty()) form += " of " + std::string(unit);
  form += (above ? " > " : " >= ") + NumberText(min);
  return FlagValue{
      .shape = std::move(shape),
      .default_text = std::move(default_text),
      .parse = [min, above, form, store = std::move(store)](
                   const std::vector<std::string>& words) {
        const std::string& text = words[0];
        double value = 0;
        const auto [end, error] =
            std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || error != std::errc() ||
            end != text.data() + text.size() || !std::isfinite(value) ||
            (above ? !(value > min) : !(value >= min))) {
          return Problem(form);
        }
        store(value);
        return Status::OK();
      }};
}

}  // namespace

Status FlagError(std::string_view flag, std::string_view text,
                 std::string_view problem) {
  std::string message = "--";
  message.append(flag).append(" '").append(text).append("': ").append(problem);
  return Status::InvalidArgument(std::move(message));
}

namespace flag {

FlagValue Switch(bool* out) {
  return FlagValue{.words = 0,
                   .shape = "",
                   .default_text = "",
                   .parse = [out](const std::vector<std::string>&) {
                     *out = true;
                     return Status::OK();
                   }};
}

FlagValue Text(std::string* out) {
  return FlagValue{.shape = "TEXT",
                   .default_text = *out,
                   .parse = [out](const std::vector<std::string>& words) {
                     *out = words[0];
                     return Status::OK();
                   }};
}

FlagValue CountInto(uint64_t min, uint64_t max, uint64_t current,
                    std::function<void(uint64_t)> store) {
  const std::string form = "must be a whole number " + RangeText(min, max, "");
  return FlagValue{
      .shape = "N",
      .default_text = std::to_string(current),
      .parse = [min, max, form, store = std::move(store)](
                   const std::vector<std::string>& words) {
        const std::string& text = words[0];
        uint64_t value = 0;
        const auto [end, error] =
            std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || error != std::errc() ||
            end != text.data() + text.size() || value < min || value > max) {
          return Problem(form);
        }
        store(value);
        return Status::OK();
      }};
}

FlagValue Number(double* out, double min, bool above) {
  return NumberValue(min, above, "", "X", NumberText(*out),
                     [out](double value) { *out = value; });
}

FlagValue Seconds(double* out, double min, bool above) {
  return NumberValue(min, above, "seconds", "SECONDS", NumberText(*out),
                     [out](double value) { *out = value; });
}

FlagValue NumberInto(double min, bool above,
                     std::function<void(double)> store) {
  return NumberValue(min, above, "", "X", "", std::move(store));
}

FlagValue CommaList(FlagValue element, std::function<void()> begin,
                    std::function<void()> commit, std::string default_text) {
  return FlagValue{
      .shape = element.shape + "," + element.shape + ",...",
      .default_text = std::move(default_text),
      .parse = [parse = std::move(element.parse), begin = std::move(begin),
                commit =
                    std::move(commit)](const std::vector<std::string>& words) {
        begin();
        const std::string_view text = words[0];
        for (size_t start = 0;;) {
          const size_t comma = std::min(text.find(',', start), text.size());
          const Status status =
              parse({std::string(text.substr(start, comma - start))});
          if (!status.ok()) {
            return Problem(status.message() + ", comma-separated");
          }
          if (comma == text.size()) break;
          start = comma + 1;
        }
        commit();
        return Status::OK();
      }};
}

FlagValue Texts(std::vector<std::string>* out) {
  auto parsed = std::make_shared<std::vector<std::string>>();
  return CommaList(
      FlagValue{.shape = "WORD",
                .default_text = "",
                .parse =
                    [parsed](const std::vector<std::string>& words) {
                      if (words[0].empty()) return Problem("must be a word");
                      parsed->push_back(words[0]);
                      return Status::OK();
                    }},
      [parsed] { parsed->clear(); }, [parsed, out] { *out = *parsed; },
      JoinList(*out));
}

FlagValue BytesInto(uint64_t min, uint64_t max, uint64_t current,
                    std::function<void(uint64_t)> store) {
  const std::string form = "must be a byte size " +
                           RangeText(min, max, "bytes") +
                           " (a whole number, optionally with B, KiB, MiB or "
                           "GiB)";
  return FlagValue{.shape = "SIZE",
                   .default_text = ByteText(current),
                   .parse = [min, max, form, store = std::move(store)](
                                const std::vector<std::string>& words) {
                     size_t bytes = 0;
                     if (!ParseByteSize(words[0], &bytes).ok() || bytes < min ||
                         bytes > max) {
                       return Problem(form);
                     }
                     store(bytes);
                     return Status::OK();
                   }};
}

FlagValue ChoiceInto(std::vector<std::string> words, size_t current,
                     std::function<void(size_t index)> store) {
  std::string shape;
  for (const std::string& word : words) {
    if (!shape.empty()) shape += '|';
    shape += word;
  }
  const std::string form = "must be " + Alternatives(words);
  std::string default_text = current < words.size() ? words[current] : "";
  return FlagValue{
      .shape = std::move(shape),
      .default_text = std::move(default_text),
      .parse = [words = std::move(words), form, store = std::move(store)](
                   const std::vector<std::string>& given) {
        for (size_t i = 0; i < words.size(); ++i) {
          if (words[i] == given[0]) {
            store(i);
            return Status::OK();
          }
        }
        return Problem(form);
      }};
}

FlagValue Choice(std::string* out, std::vector<std::string> words) {
  std::vector<std::pair<std::string, std::string>> choices;
  for (const std::string& word : words) choices.emplace_back(word, word);
  return Choice<std::string>(out, std::move(choices));
}

FlagValue Repeated(std::vector<std::string>* out) {
  std::string default_text;
  for (const std::string& text : *out) {
    if (!default_text.empty()) default_text += ' ';
    default_text += text;
  }
  return FlagValue{.repeatable = true,
                   .shape = "TEXT",
                   .default_text = std::move(default_text),
                   .parse = [out, replaced = false](
                                const std::vector<std::string>& words) mutable {
                     if (!replaced) out->clear();
                     replaced = true;
                     out->push_back(words[0]);
                     return Status::OK();
                   }};
}

FlagValue Words(std::vector<std::string>* out, size_t count) {
  return FlagValue{.words = count,
                   .shape = "",
                   .default_text = "",
                   .parse = [out](const std::vector<std::string>& words) {
                     *out = words;
                     return Status::OK();
                   }};
}

FlagValue Parsed(std::function<Status(std::string_view text)> parse) {
  return FlagValue{.shape = "TEXT",
                   .default_text = "",
                   .parse = [parse = std::move(parse)](
                                const std::vector<std::string>& words) {
                     return parse(words[0]);
                   }};
}

}  // namespace flag
}  // namespace locator
