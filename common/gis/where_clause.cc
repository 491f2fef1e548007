#include "common/gis/where_clause.h"

#include <array>
#include <cctype>
#include <string>

namespace locator::gis {
namespace {

constexpr std::array<std::string_view, 9> kKeywords = {
    "AND", "OR", "NOT", "IS", "NULL", "IN", "BETWEEN", "LIKE", "ESCAPE"};
// Longest first, so that "<=" is not read as "<".
constexpr std::array<std::string_view, 15> kSymbols = {
    "<=", ">=", "<>", "!=", "=", "<", ">", "+",
    "-",  "*",  "/",  "%",  "(", ")", ","};
constexpr std::array<std::string_view, 7> kComparisons = {"=",  "!=", "<>", "<",
                                                          "<=", ">",  ">="};

enum class Kind { kEnd, kNumber, kString, kField, kKeyword, kSymbol };

struct Token {
  Kind kind = Kind::kEnd;
  std::string text;  // a keyword in upper case, a symbol, else as written
  size_t offset = 0;
};

bool IsWordStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool IsWordChar(char c) {
  return IsWordStart(c) || std::isdigit(static_cast<unsigned char>(c));
}
bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)); }

// A recursive-descent check of the grammar in the header; the first error
// ends it.
class Checker {
 public:
  explicit Checker(std::string_view where) : where_(where) { Advance(); }

  Status Check() {
    Expr(0);
    if (error_.empty() && token_.kind != Kind::kEnd) Fail("the end");
    if (error_.empty()) return Status::OK();
    return Status::InvalidArgument(error_);
  }

 private:
  // Reads the next token into token_.
  void Advance() {
    while (at_ < where_.size() &&
           std::isspace(static_cast<unsigned char>(where_[at_]))) {
      ++at_;
    }
    token_ = Token{Kind::kEnd, "", at_};
    if (at_ == where_.size()) return;
    const char c = where_[at_];
    if (IsDigit(c) ||
        (c == '.' && at_ + 1 < where_.size() && IsDigit(where_[at_ + 1]))) {
      return Number();
    }
    if (c == '\'' || c == '"') return Quoted(c);
    // SQLite would skip what a comment holds; nothing here needs one.
    if (where_.substr(at_).starts_with("--") ||
        where_.substr(at_).starts_with("/*")) {
      Fail("no comment");
      at_ = where_.size();
      return;
    }
    if (IsWordStart(c)) return Word();
    for (std::string_view symbol : kSymbols) {
      if (where_.substr(at_).starts_with(symbol)) {
        token_ = Token{Kind::kSymbol, std::string(symbol), at_};
        at_ += symbol.size();
        return;
      }
    }
    Fail("a field, a literal or an operator");
    at_ = where_.size();
  }

  void Number() {
    const size_t start = at_;
    while (at_ < where_.size() && IsDigit(where_[at_])) ++at_;
    if (at_ < where_.size() && where_[at_] == '.') ++at_;
    while (at_ < where_.size() && IsDigit(where_[at_])) ++at_;
    if (at_ < where_.size() && (where_[at_] == 'e' || where_[at_] == 'E')) {
      ++at_;
      if (at_ < where_.size() && (where_[at_] == '+' || where_[at_] == '-')) {
        ++at_;
      }
      while (at_ < where_.size() && IsDigit(where_[at_])) ++at_;
    }
    token_ = Token{Kind::kNumber,
                   std::string(where_.substr(start, at_ - start)), start};
  }

  // A 'string' or a "field"; a doubled quote stands for itself.
  void Quoted(char quote) {
    const size_t start = at_++;
    while (at_ < where_.size()) {
      if (where_[at_++] != quote) continue;
      if (at_ < where_.size() && where_[at_] == quote) {
        ++at_;
        continue;
      }
      token_ = Token{quote == '\'' ? Kind::kString : Kind::kField,
                     std::string(where_.substr(start, at_ - start)), start};
      return;
    }
    Fail(quote == '\'' ? "a closing quote (') of the string"
                       : "a closing quote (\") of the field");
    at_ = where_.size();
  }

  void Word() {
    const size_t start = at_;
    while (at_ < where_.size() && IsWordChar(where_[at_])) ++at_;
    std::string word(where_.substr(start, at_ - start));
    std::string upper = word;
    for (char& c : upper) c = std::toupper(static_cast<unsigned char>(c));
    for (std::string_view keyword : kKeywords) {
      if (upper == keyword) {
        token_ = Token{Kind::kKeyword, upper, start};
        return;
      }
    }
    token_ = Token{Kind::kField, word, start};
  }

  bool Is(Kind kind, std::string_view text) const {
    return error_.empty() && token_.kind == kind && token_.text == text;
  }
  bool Accept(Kind kind, std::string_view text) {
    if (!Is(kind, text)) return false;
    Advance();
    return true;
  }
  void Expect(Kind kind, std::string_view text) {
    if (Accept(kind, text)) return;
    std::string quoted(1, '\'');  // GCC 12's false -Wrestrict on "'" + ...
    quoted.append(text);
    quoted.push_back('\'');
    Fail(quoted);
  }

  // Records "expected `what`" at the current token, if nothing failed yet.
  void Fail(const std::string& what) {
    if (!error_.empty()) return;
    constexpr size_t kQuoted = 20;
    const std::string_view found = where_.substr(token_.offset, kQuoted);
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on
    // "'" + std::string(...).
    error_ = "at byte " + std::to_string(token_.offset) + ", expected " + what;
    if (found.empty()) {
      error_.append(", found the end");
    } else {
      error_.append(", found '");
      error_.append(found);
      error_.push_back('\'');
    }
    error_.append(
        " (a where clause here compares fields and literals: no functions, "
        "no sub-selects)");
  }

  bool TooDeep(int depth) {
    if (depth <= kMaxWhereNesting) return false;
    Fail("at most " + std::to_string(kMaxWhereNesting) + " levels of nesting");
    return true;
  }

  void Expr(int depth) {
    if (TooDeep(depth)) return;
    And(depth);
    while (Accept(Kind::kKeyword, "OR")) And(depth);
  }

  void And(int depth) {
    Not(depth);
    while (Accept(Kind::kKeyword, "AND")) Not(depth);
  }

  void Not(int depth) {
    if (TooDeep(depth)) return;
    if (Accept(Kind::kKeyword, "NOT")) return Not(depth + 1);
    Predicate(depth);
  }

  void Predicate(int depth) {
    Sum(depth);
    for (std::string_view comparison : kComparisons) {
      if (Accept(Kind::kSymbol, comparison)) return Sum(depth);
    }
    if (Accept(Kind::kKeyword, "IS")) {
      Accept(Kind::kKeyword, "NOT");
      return Expect(Kind::kKeyword, "NULL");
    }
    const bool negated = Accept(Kind::kKeyword, "NOT");
    if (Accept(Kind::kKeyword, "BETWEEN")) {
      Sum(depth);
      Expect(Kind::kKeyword, "AND");
      return Sum(depth);
    }
    if (Accept(Kind::kKeyword, "IN")) {
      Expect(Kind::kSymbol, "(");
      do {
        Sum(depth);
      } while (Accept(Kind::kSymbol, ","));
      return Expect(Kind::kSymbol, ")");
    }
    if (Accept(Kind::kKeyword, "LIKE")) {
      Sum(depth);
      if (Accept(Kind::kKeyword, "ESCAPE")) Sum(depth);
      return;
    }
    if (negated) Fail("BETWEEN, IN or LIKE after NOT");
  }

  void Sum(int depth) {
    Product(depth);
    while (Accept(Kind::kSymbol, "+") || Accept(Kind::kSymbol, "-")) {
      Product(depth);
    }
  }

  void Product(int depth) {
    Unary(depth);
    while (Accept(Kind::kSymbol, "*") || Accept(Kind::kSymbol, "/") ||
           Accept(Kind::kSymbol, "%")) {
      Unary(depth);
    }
  }

  void Unary(int depth) {
    if (TooDeep(depth) || !error_.empty()) return;
    if (Accept(Kind::kSymbol, "+") || Accept(Kind::kSymbol, "-")) {
      return Unary(depth + 1);
    }
    if (Accept(Kind::kSymbol, "(")) {
      Expr(depth + 1);
      return Expect(Kind::kSymbol, ")");
    }
    if (token_.kind == Kind::kNumber || token_.kind == Kind::kString ||
        token_.kind == Kind::kField || Is(Kind::kKeyword, "NULL")) {
      return Advance();
    }
    Fail("a field, a literal or '('");
  }

  const std::string_view where_;
  size_t at_ = 0;
  Token token_;
  std::string error_;
};

}  // namespace

Status CheckPlainWhereClause(std::string_view where) {
  if (where.size() > kMaxWhereBytes) {
    return Status::InvalidArgument(
        "a where clause of " + std::to_string(where.size()) +
        " bytes; at most " + std::to_string(kMaxWhereBytes) + " are accepted");
  }
  return Checker(where).Check();
}

}  // namespace locator::gis
