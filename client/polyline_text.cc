#include "client/polyline_text.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "common/status_macros.h"
#include "common/str_cat.h"
#include "common/text_fields.h"

namespace locator {
namespace {

constexpr std::string_view kLineString = "LINESTRING";

bool IsSpace(char c) { return std::isspace(static_cast<unsigned char>(c)); }

std::string_view Trim(std::string_view text) {
  while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && IsSpace(text.back())) text.remove_suffix(1);
  return text;
}

// Removes `word` (case-insensitive) from the front of `text`; false if
// `text` does not start with it.
bool ConsumeWord(std::string_view word, std::string_view* text) {
  if (text->size() < word.size()) return false;
  for (size_t i = 0; i < word.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>((*text)[i])) != word[i]) {
      return false;
    }
  }
  text->remove_prefix(word.size());
  *text = Trim(*text);
  return true;
}

// `text` split at every `separator` (whitespace when it is ' '), empty
// pieces dropped.
std::vector<std::string_view> Split(std::string_view text, char separator) {
  std::vector<std::string_view> pieces;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i) {
    const bool at_end = i == text.size();
    if (at_end ||
        (separator == ' ' ? IsSpace(text[i]) : text[i] == separator)) {
      const std::string_view piece = Trim(text.substr(start, i - start));
      if (!piece.empty()) pieces.push_back(piece);
      start = i + 1;
    }
  }
  return pieces;
}

Status ParseCoordinate(std::string_view text, double* value) {
  if (ParseDouble(text, value)) return Status::OK();
  return Status::InvalidArgument(StrCat({"'", text, "' is not a number"}));
}

// "x,y" pairs separated by whitespace.
Status ParsePairs(std::string_view text, std::vector<Point2>* vertices) {
  for (std::string_view pair : Split(text, ' ')) {
    const size_t comma = pair.find(',');
    if (comma == std::string_view::npos) {
      return Status::InvalidArgument(
          StrCat({"'", pair, "' is not an x,y pair"}));
    }
    Point2 vertex;
    RETURN_IF_ERROR(ParseCoordinate(pair.substr(0, comma), &vertex.x));
    RETURN_IF_ERROR(ParseCoordinate(pair.substr(comma + 1), &vertex.y));
    vertices->push_back(vertex);
  }
  return Status::OK();
}

// The WKT after "LINESTRING": "[Z] (x y[ z], ...)".
Status ParseWktLineString(std::string_view text,
                          std::vector<Point2>* vertices) {
  const size_t coordinates = ConsumeWord("Z", &text) ? 3 : 2;
  if (text.size() < 2 || text.front() != '(' || text.back() != ')') {
    return Status::InvalidArgument(
        "WKT: expected LINESTRING (x y, ...) with its parentheses");
  }
  text = text.substr(1, text.size() - 2);
  for (std::string_view vertex_text : Split(text, ',')) {
    const std::vector<std::string_view> numbers = Split(vertex_text, ' ');
    if (numbers.size() != coordinates) {
      return Status::InvalidArgument(
          StrCat({"WKT: vertex '", vertex_text, "' has ",
                  std::to_string(numbers.size()), " coordinates, not ",
                  std::to_string(coordinates)}));
    }
    Point2 vertex;
    RETURN_IF_ERROR(ParseCoordinate(numbers[0], &vertex.x));
    RETURN_IF_ERROR(ParseCoordinate(numbers[1], &vertex.y));
    if (coordinates == 3) {
      double ignored_z;
      RETURN_IF_ERROR(ParseCoordinate(numbers[2], &ignored_z));
    }
    vertices->push_back(vertex);
  }
  return Status::OK();
}

}  // namespace

Status ParsePolyline(std::string_view text, std::vector<Point2>* vertices) {
  vertices->clear();
  text = Trim(text);
  // WKT starts with a word: the geometry's type.
  const std::string_view first_word =
      text.substr(0, text.find_first_of(" \t\n("));
  const bool wkt =
      !first_word.empty() &&
      std::all_of(first_word.begin(), first_word.end(), [](char c) {
        return std::isalpha(static_cast<unsigned char>(c));
      });
  Status status;
  if (!wkt) {
    status = ParsePairs(text, vertices);
  } else if (first_word.size() == kLineString.size() &&
             ConsumeWord(kLineString, &text)) {
    status = ParseWktLineString(text, vertices);
  } else {
    status = Status::InvalidArgument(
        StrCat({"WKT: only a LINESTRING is a line, not ", first_word}));
  }
  if (status.ok() && vertices->size() < 2) {
    status = Status::InvalidArgument("a line needs at least 2 vertices, not " +
                                     std::to_string(vertices->size()));
  }
  return status;
}

}  // namespace locator
