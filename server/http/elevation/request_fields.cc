#include "server/http/elevation/request_fields.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>

#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Whether the media type of `content_type` (parameters after ';' ignored,
// case-insensitive) is `media`.
bool HasMediaType(std::optional<std::string_view> content_type,
                  std::string_view media) {
  if (!content_type.has_value()) return false;
  std::string_view type = content_type->substr(0, content_type->find(';'));
  while (!type.empty() && (type.back() == ' ' || type.back() == '\t')) {
    type.remove_suffix(1);
  }
  while (!type.empty() && (type.front() == ' ' || type.front() == '\t')) {
    type.remove_prefix(1);
  }
  if (type.size() != media.size()) return false;
  for (size_t i = 0; i < type.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(type[i])) != media[i]) {
      return false;
    }
  }
  return true;
}

// A JSON number as Python's str() of a number would show it, as Open Topo
// Data reads a JSON body: integers without a fraction.
std::string JsonNumberText(double value) {
  if (std::isfinite(value) && std::trunc(value) == value &&
      std::fabs(value) < 9.007199254740992e15) {
    return std::to_string(static_cast<int64_t>(value));
  }
  return NumberText(value);
}

// Whether `json` nests objects and arrays (outside strings) deeper than
// `limit`. Protobuf's JSON parser recurses once per level into a Struct,
// so a body nested 10^5 deep would overflow the stack; a body of fields
// that are strings or numbers nests once.
bool NestsDeeperThan(std::string_view json, size_t limit) {
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      if (++depth > limit) return true;
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
  }
  return false;
}

}  // namespace

StatusOr<std::string> PercentDecoded(std::string_view text,
                                     std::string_view field) {
  std::string decoded;
  decoded.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '+') {
      c = ' ';
    } else if (c == '%') {
      const bool complete = i + 2 < text.size();
      const int high = complete ? HexDigit(text[i + 1]) : -1;
      const int low = complete ? HexDigit(text[i + 2]) : -1;
      if (high < 0 || low < 0) {
        return Status::InvalidArgument(
            std::string(field) + ": a '%' at byte " + std::to_string(i) +
            " is not followed by two hexadecimal digits in " +
            QuotedInput(text));
      }
      c = static_cast<char>(high * 16 + low);
      i += 2;
    }
    if (c == '\0') {
      return Status::InvalidArgument(std::string(field) +
                                     ": a NUL byte is not allowed");
    }
    decoded.push_back(c);
  }
  return decoded;
}

StatusOr<RequestFields> RequestFields::OfForm(std::string_view form) {
  RequestFields fields;
  while (!form.empty()) {
    const size_t amp = form.find('&');
    const std::string_view pair = form.substr(0, amp);
    if (!pair.empty()) {
      const size_t equals = pair.find('=');
      ASSIGN_OR_RETURN(std::string name,
                       PercentDecoded(pair.substr(0, equals), "a field name"));
      const std::string_view raw = equals == std::string_view::npos
                                       ? std::string_view()
                                       : pair.substr(equals + 1);
      ASSIGN_OR_RETURN(std::string value,
                       PercentDecoded(raw, QuotedInput(name)));
      fields.fields_.emplace_back(std::move(name), std::move(value));
    }
    if (amp == std::string_view::npos) break;
    form.remove_prefix(amp + 1);
  }
  return fields;
}

StatusOr<RequestFields> RequestFields::Of(const HttpRequest& request) {
  if (request.method != "POST") return OfForm(request.query);
  const std::optional<std::string_view> type = request.Header("content-type");
  if (HasMediaType(type, "application/x-www-form-urlencoded")) {
    return OfForm(request.body);
  }
  if (!HasMediaType(type, "application/json")) {
    return Status::InvalidArgument(
        "a POST body must be application/json or "
        "application/x-www-form-urlencoded; Content-Type is " +
        QuotedInput(type.value_or("absent")));
  }
  if (NestsDeeperThan(request.body, 1)) {
    return Status::InvalidArgument(
        "Invalid JSON: the body must be one object whose fields are strings "
        "or numbers, as {\"locations\": \"lat,lng|lat,lng\"}; it nests "
        "deeper");
  }
  google::protobuf::Struct object;
  google::protobuf::util::JsonParseOptions options;
  if (const auto parsed = google::protobuf::util::JsonStringToMessage(
          request.body, &object, options);
      !parsed.ok()) {
    const std::string_view error(parsed.message().data(),
                                 parsed.message().size());
    return Status::InvalidArgument(
        "Invalid JSON: the body is not a JSON object: " +
        TruncatedMessage(error.substr(0, error.find('\n')),
                         2 * kQuotedInputBytes));
  }
  RequestFields fields;
  for (const auto& [name, value] : object.fields()) {
    switch (value.kind_case()) {
      case google::protobuf::Value::kStringValue:
        if (value.string_value().find('\0') != std::string::npos) {
          return Status::InvalidArgument(QuotedInput(name) +
                                         ": a NUL byte is not allowed");
        }
        fields.fields_.emplace_back(name, value.string_value());
        break;
      case google::protobuf::Value::kNumberValue:
        fields.fields_.emplace_back(name, JsonNumberText(value.number_value()));
        break;
      default:
        return Status::InvalidArgument(
            QuotedInput(name) +
            ": a JSON body's fields must be strings or numbers, as in "
            "{\"locations\": \"lat,lng|lat,lng\"}");
    }
  }
  return fields;
}

std::optional<std::string_view> RequestFields::Get(
    std::string_view name) const {
  for (const auto& [field, value] : fields_) {
    if (field == name) return value;
  }
  return std::nullopt;
}

}  // namespace locator
