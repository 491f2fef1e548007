#include "server/http/edr/wkt_coordinates.h"

#include <cctype>
#include <string>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "common/text_fields.h"

namespace locator {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Reads `text` left to right; every error names the byte it stopped at.
class WktReader {
 public:
  WktReader(std::string_view text, size_t max_points)
      : text_(text), max_points_(max_points) {}

  StatusOr<WktCoordinates> Read() {
    WktCoordinates geometry;
    const std::string keyword = Word();
    if (keyword == "POINT") {
      geometry.type = WktCoordinates::Type::kPoint;
    } else if (keyword == "MULTIPOINT") {
      geometry.type = WktCoordinates::Type::kMultiPoint;
    } else if (keyword == "LINESTRING") {
      geometry.type = WktCoordinates::Type::kLineString;
    } else {
      return Error(keyword.empty()
                       ? "expected POINT, MULTIPOINT or LINESTRING"
                       : "unsupported geometry " + QuotedInput(keyword) +
                             "; expected POINT, MULTIPOINT or LINESTRING");
    }
    if (const std::string dimension = Word(); !dimension.empty()) {
      return Error(dimension == "EMPTY"
                       ? "an EMPTY geometry has no point to answer"
                       : "only 2D coordinates (x y) are supported, not " +
                             QuotedInput(dimension));
    }
    RETURN_IF_ERROR(Expect('('));
    if (geometry.type == WktCoordinates::Type::kMultiPoint && Peek() == '(') {
      // MULTIPOINT ((x y), (x y)).
      do {
        RETURN_IF_ERROR(Expect('('));
        RETURN_IF_ERROR(ReadPoint(&geometry.points));
        RETURN_IF_ERROR(Expect(')'));
      } while (Consume(','));
    } else {
      do {
        RETURN_IF_ERROR(ReadPoint(&geometry.points));
      } while (geometry.type != WktCoordinates::Type::kPoint && Consume(','));
    }
    RETURN_IF_ERROR(Expect(')'));
    SkipSpace();
    if (pos_ != text_.size()) return Error("text after the geometry");
    if (geometry.type == WktCoordinates::Type::kLineString &&
        geometry.points.size() < 2) {
      return Error("a LINESTRING needs at least 2 points");
    }
    return geometry;
  }

 private:
  Status Error(const std::string& problem) const {
    return Status::InvalidArgument("coords: " + problem + " at byte " +
                                   std::to_string(pos_) + " of " +
                                   QuotedInput(text_));
  }
  void SkipSpace() {
    while (pos_ < text_.size() && IsSpace(text_[pos_])) ++pos_;
  }
  char Peek() {
    SkipSpace();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }
  bool Consume(char c) {
    if (Peek() != c) return false;
    ++pos_;
    return true;
  }
  Status Expect(char c) {
    if (Consume(c)) return Status::OK();
    return Error(std::string("expected '") + c + "'");
  }
  // The letters at the position, upper-cased ("" if none).
  std::string Word() {
    SkipSpace();
    std::string word;
    while (pos_ < text_.size() &&
           std::isalpha(static_cast<unsigned char>(text_[pos_])) &&
           word.size() <= 16) {
      word.push_back(static_cast<char>(
          std::toupper(static_cast<unsigned char>(text_[pos_]))));
      ++pos_;
    }
    return word;
  }
  Status ReadCoordinate(double* value) {
    SkipSpace();
    const size_t start = pos_;
    while (pos_ < text_.size() && !IsSpace(text_[pos_]) && text_[pos_] != ',' &&
           text_[pos_] != '(' && text_[pos_] != ')') {
      ++pos_;
    }
    const std::string_view number = text_.substr(start, pos_ - start);
    if (number.empty()) {
      pos_ = start;
      return Error("expected a coordinate");
    }
    switch (ParseNumber(number, value)) {
      case NumberKind::kFinite:
        return Status::OK();
      case NumberKind::kNonFinite:
        pos_ = start;
        return Error("coordinate " + QuotedInput(number) +
                     " is not a finite number");
      case NumberKind::kNotANumber:
        break;
    }
    pos_ = start;
    return Error("coordinate " + QuotedInput(number) + " is not a number");
  }
  Status ReadPoint(std::vector<Point2>* points) {
    if (points->size() == max_points_) {
      return Error("more than " + std::to_string(max_points_) +
                   " points, this server's limit");
    }
    Point2 p;
    RETURN_IF_ERROR(ReadCoordinate(&p.x));
    RETURN_IF_ERROR(ReadCoordinate(&p.y));
    const char next = Peek();
    if (pos_ == text_.size()) return Error("expected ')'");
    if (next != ',' && next != ')') {
      return Error("a point has two coordinates, x y");
    }
    points->push_back(p);
    return Status::OK();
  }

  const std::string_view text_;
  const size_t max_points_;
  size_t pos_ = 0;
};

}  // namespace

StatusOr<WktCoordinates> ParseWktCoordinates(std::string_view text,
                                             size_t max_points) {
  return WktReader(text, max_points).Read();
}

}  // namespace locator
