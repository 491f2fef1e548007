#include "tests/server/http/json_value.h"

#include <charconv>
#include <stdexcept>

namespace locator::test {
namespace {

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  Status Parse(JsonValue* out) {
    SkipSpace();
    if (!Value(out, 0)) return Error();
    SkipSpace();
    if (at_ != text_.size()) return Error();
    return Status::OK();
  }

 private:
  static constexpr int kMaxDepth = 64;

  Status Error() const {
    return Status::InvalidArgument("invalid JSON at offset " +
                                   std::to_string(at_));
  }
  bool More() const { return at_ < text_.size(); }
  char Peek() const { return More() ? text_[at_] : '\0'; }
  void SkipSpace() {
    while (More() && (Peek() == ' ' || Peek() == '\t' || Peek() == '\n' ||
                      Peek() == '\r')) {
      ++at_;
    }
  }
  bool Consume(char c) {
    if (Peek() != c) return false;
    ++at_;
    return true;
  }
  bool Literal(std::string_view word) {
    if (text_.substr(at_, word.size()) != word) return false;
    at_ += word.size();
    return true;
  }

  bool Value(JsonValue* out, int depth) {
    if (depth > kMaxDepth) return false;
    switch (Peek()) {
      case '{':
        return Object(out, depth);
      case '[':
        return Array(out, depth);
      case '"': {
        std::string s;
        if (!String(&s)) return false;
        out->value = std::move(s);
        return true;
      }
      case 't':
        out->value = true;
        return Literal("true");
      case 'f':
        out->value = false;
        return Literal("false");
      case 'n':
        out->value = nullptr;
        return Literal("null");
      default:
        return Number(out);
    }
  }

  // After an opening bracket: "element (, element)* close" or just
  // "close"; `element` parses one element (whitespace around it skipped).
  template <class Element>
  bool Elements(char close, Element element) {
    ++at_;
    SkipSpace();
    if (Consume(close)) return true;
    do {
      SkipSpace();
      if (!element()) return false;
      SkipSpace();
    } while (Consume(','));
    return Consume(close);
  }

  bool Object(JsonValue* out, int depth) {
    JsonObject object;
    const bool ok = Elements('}', [&] {
      std::string name;
      JsonValue member;
      if (!String(&name)) return false;
      SkipSpace();
      if (!Consume(':')) return false;
      SkipSpace();
      return Value(&member, depth + 1) &&
             object.emplace(std::move(name), std::move(member)).second;
    });
    out->value = std::move(object);
    return ok;
  }

  bool Array(JsonValue* out, int depth) {
    JsonArray array;
    const bool ok =
        Elements(']', [&] { return Value(&array.emplace_back(), depth + 1); });
    out->value = std::move(array);
    return ok;
  }

  // The JSON number grammar, checked before from_chars converts it.
  bool Number(JsonValue* out) {
    const size_t start = at_;
    Consume('-');
    if (Consume('0')) {
    } else if (!Digits()) {
      return false;
    }
    if (Consume('.') && !Digits()) return false;
    if (Peek() == 'e' || Peek() == 'E') {
      ++at_;
      if (!Consume('+')) Consume('-');
      if (!Digits()) return false;
    }
    double value = 0;
    const auto [end, error] =
        std::from_chars(text_.data() + start, text_.data() + at_, value);
    if (error != std::errc() || end != text_.data() + at_) return false;
    out->value = value;
    return true;
  }
  bool Digits() {
    const size_t start = at_;
    while (Peek() >= '0' && Peek() <= '9') ++at_;
    return at_ > start;
  }

  bool Hex4(uint32_t* code) {
    if (at_ + 4 > text_.size()) return false;
    const auto [end, error] =
        std::from_chars(text_.data() + at_, text_.data() + at_ + 4, *code, 16);
    if (error != std::errc() || end != text_.data() + at_ + 4) return false;
    at_ += 4;
    return true;
  }

  static void AppendUtf8(uint32_t code, std::string* out) {
    if (code < 0x80) {
      *out += static_cast<char>(code);
    } else if (code < 0x800) {
      *out += static_cast<char>(0xC0 | (code >> 6));
      *out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      *out += static_cast<char>(0xE0 | (code >> 12));
      *out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      *out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      *out += static_cast<char>(0xF0 | (code >> 18));
      *out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      *out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      *out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  bool Escape(std::string* out) {
    const char c = Peek();
    ++at_;
    switch (c) {
      case '"':
      case '\\':
      case '/':
        *out += c;
        return true;
      case 'b':
        *out += '\b';
        return true;
      case 'f':
        *out += '\f';
        return true;
      case 'n':
        *out += '\n';
        return true;
      case 'r':
        *out += '\r';
        return true;
      case 't':
        *out += '\t';
        return true;
      case 'u': {
        uint32_t code = 0;
        if (!Hex4(&code)) return false;
        if (code >= 0xD800 && code < 0xDC00) {
          uint32_t low = 0;
          if (!Literal("\\u") || !Hex4(&low) || low < 0xDC00 || low > 0xDFFF) {
            return false;
          }
          code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        } else if (code >= 0xDC00 && code < 0xE000) {
          return false;
        }
        AppendUtf8(code, out);
        return true;
      }
      default:
        return false;
    }
  }

  bool String(std::string* out) {
    if (!Consume('"')) return false;
    while (More() && Peek() != '"') {
      const auto c = static_cast<unsigned char>(Peek());
      if (c < 0x20) return false;
      if (c == '\\') {
        ++at_;
        if (!Escape(out)) return false;
      } else {
        *out += static_cast<char>(c);
        ++at_;
      }
    }
    return Consume('"');
  }

  const std::string_view text_;
  size_t at_ = 0;
};

}  // namespace

const JsonValue& JsonValue::operator[](std::string_view name) const {
  const JsonObject& members = object();
  const auto found = members.find(name);
  if (found == members.end()) {
    throw std::out_of_range("no JSON member " + std::string(name));
  }
  return found->second;
}

Status ParseJson(std::string_view text, JsonValue* out) {
  return Parser(text).Parse(out);
}

}  // namespace locator::test
