// Constraints from WKT text (see ParseWktConstraints in dataset.h): a
// tokenizer that keeps line numbers and a recursive-descent reader of the
// geometries that constrain a surface.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "server/core/dataset/dataset_text.h"

namespace locator {

using dataset_text::Cat;
using dataset_text::Quoted;
using dataset_text::Where;

namespace {

enum class TokenKind {
  kWord,
  kNumber,
  kOpen,
  kClose,
  kComma,
  kSemicolon,
  kEnd
};

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string text;  // as written
  std::string word;  // upper-cased, for keywords
  size_t line = 0;
};

// Splits WKT text into words, numbers and punctuation, with line numbers.
class WktTokens {
 public:
  explicit WktTokens(std::string_view text) : text_(text) { Advance(); }

  const Token& Peek() const { return next_; }
  Token Take() {
    Token t = std::move(next_);
    Advance();
    return t;
  }

 private:
  static bool IsSpace(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
  }
  static bool IsPunctuation(char c) {
    return c == '(' || c == ')' || c == ',' || c == ';';
  }

  void Advance() {
    while (pos_ < text_.size() && IsSpace(text_[pos_])) {
      line_ += text_[pos_++] == '\n';
    }
    next_ = Token{TokenKind::kEnd, "", "", line_};
    if (pos_ == text_.size()) return;
    const size_t start = pos_;
    const char c = text_[pos_++];
    if (!IsPunctuation(c)) {
      while (pos_ < text_.size() && !IsSpace(text_[pos_]) &&
             !IsPunctuation(text_[pos_])) {
        ++pos_;
      }
    }
    next_.text = std::string(text_.substr(start, pos_ - start));
    next_.word = next_.text;
    for (char& u : next_.word) u = static_cast<char>(std::toupper(u));
    next_.kind = c == '('   ? TokenKind::kOpen
                 : c == ')' ? TokenKind::kClose
                 : c == ',' ? TokenKind::kComma
                 : c == ';' ? TokenKind::kSemicolon
                 : std::isalpha(static_cast<unsigned char>(c)) &&
                         next_.word != "NAN" && next_.word != "INF" &&
                         next_.word != "INFINITY"
                     ? TokenKind::kWord
                     : TokenKind::kNumber;
  }

  std::string_view text_;
  size_t pos_ = 0;
  size_t line_ = 1;
  Token next_;
};

// One coordinate tuple as read, and the geometry's coordinate dimension.
struct Coordinates {
  std::vector<Point2> points;
  std::vector<double> z;
};

class WktReader {
 public:
  WktReader(std::string_view text, std::string_view filename,
            DatasetConstraints* out)
      : tokens_(text), filename_(filename), out_(out) {}

  Status ReadAll() {
    if (tokens_.Peek().kind == TokenKind::kEnd) {
      return Status::InvalidArgument(Cat(filename_, ": no geometries"));
    }
    while (tokens_.Peek().kind != TokenKind::kEnd) {
      RETURN_IF_ERROR(ReadGeometry());
      if (tokens_.Peek().kind == TokenKind::kSemicolon) tokens_.Take();
    }
    return Status::OK();
  }

 private:
  Status Error(const Token& at, std::string_view what) const {
    return Where{filename_, at.line}.Error(what);
  }
  // "file:line" of a token.
  std::string At(const Token& t) const {
    return Where{filename_, t.line}.Prefix();
  }

  Status Expect(TokenKind kind, std::string_view what) {
    const Token t = tokens_.Take();
    if (t.kind == kind) return Status::OK();
    return Error(t, Cat("expected ", what, ", found ", Describe(t)));
  }

  static std::string Describe(const Token& t) {
    return t.kind == TokenKind::kEnd ? "the end of the file" : Quoted(t.text);
  }

  // A geometry: its tag, an optional Z, then EMPTY or its body.
  Status ReadGeometry() {
    const Token tag = tokens_.Take();
    if (tag.kind != TokenKind::kWord) {
      return Error(tag, Cat("expected a geometry (LINESTRING, POLYGON, "
                            "MULTIPOLYGON, ...), found ",
                            Describe(tag)));
    }
    dimension_ = 0;
    if (tokens_.Peek().kind == TokenKind::kWord &&
        tokens_.Peek().word != "EMPTY") {
      const Token dim = tokens_.Take();
      if (dim.word != "Z") {
        return Error(dim, Cat(tag.word, " ", dim.word,
                              ": only 2D and Z coordinates are supported"));
      }
      dimension_ = 3;
    }
    if (tokens_.Peek().kind == TokenKind::kWord) {
      const Token empty = tokens_.Take();
      if (empty.word == "EMPTY") return Status::OK();
      return Error(empty, Cat("expected '(' or EMPTY after ", tag.word,
                              ", found ", Describe(empty)));
    }
    if (tag.word == "LINESTRING") return ReadLineString(tag);
    if (tag.word == "MULTILINESTRING") {
      return ReadList(tag, &WktReader::ReadLineString);
    }
    if (tag.word == "POLYGON") return ReadPolygon(tag);
    if (tag.word == "MULTIPOLYGON") {
      return ReadList(tag, &WktReader::ReadPolygon);
    }
    if (tag.word == "GEOMETRYCOLLECTION") {
      return ReadList(tag, &WktReader::ReadMember);
    }
    return Error(tag, Cat(tag.text,
                          " is not a constraint: expected LINESTRING, "
                          "MULTILINESTRING, POLYGON, MULTIPOLYGON or "
                          "GEOMETRYCOLLECTION"));
  }

  // A GEOMETRYCOLLECTION's member: a geometry with its own tag. Nesting is
  // bounded, so that no input can exhaust the stack.
  Status ReadMember(const Token& collection) {
    if (depth_ == kMaxDepth) {
      return Error(collection,
                   Cat("GEOMETRYCOLLECTIONs nested deeper than ", kMaxDepth));
    }
    ++depth_;
    Status s = ReadGeometry();
    --depth_;
    return s;
  }

  // '(' item {',' item} ')', each item read by `read`.
  Status ReadList(const Token& tag, Status (WktReader::*read)(const Token&)) {
    Status s = Expect(TokenKind::kOpen, Cat("'(' after ", tag.word));
    while (s.ok()) {
      s = (this->*read)(tag);
      if (!s.ok() || tokens_.Peek().kind != TokenKind::kComma) break;
      tokens_.Take();
    }
    if (!s.ok()) return s;
    return Expect(TokenKind::kClose, Cat("',' or ')' in ", tag.word));
  }

  // '(' x y [z] {',' x y [z]} ')'.
  Status ReadCoordinates(const Token& owner, Coordinates* c) {
    RETURN_IF_ERROR(
        Expect(TokenKind::kOpen, Cat("'(' of ", owner.word, "'s points")));
    do {
      if (!c->points.empty()) tokens_.Take();  // the ','
      double v[3];
      int count = 0;
      const Token first = tokens_.Peek();
      while (tokens_.Peek().kind == TokenKind::kNumber) {
        const Token t = tokens_.Take();
        if (count == 3) return Error(t, "more than 3 coordinates in a point");
        const NumberKind kind = ParseNumber(t.text, &v[count++]);
        if (kind != NumberKind::kFinite) {
          return Error(t, kind == NumberKind::kNonFinite
                              ? Cat("non-finite coordinate ", Quoted(t.text))
                              : Cat(Quoted(t.text), " is not a number"));
        }
      }
      if (count < 2) {
        return Error(tokens_.Peek(), Cat("expected a coordinate, found ",
                                         Describe(tokens_.Peek())));
      }
      if (dimension_ == 0) dimension_ = count;
      if (count != dimension_) {
        return Error(first, Cat("a point with ", count,
                                " coordinates among points with ", dimension_));
      }
      c->points.push_back({v[0], v[1]});
      if (count == 3) c->z.push_back(v[2]);
    } while (tokens_.Peek().kind == TokenKind::kComma);
    return Expect(TokenKind::kClose, "',' or ')' after a point");
  }

  Status ReadLineString(const Token& tag) {
    const Token start = tokens_.Peek();
    Coordinates c;
    RETURN_IF_ERROR(ReadCoordinates(tag, &c));
    if (c.points.size() < 2) {
      return Error(tag, "a LINESTRING needs at least 2 points");
    }
    out_->breaklines.push_back({std::move(c.points), std::move(c.z),
                                Cat("the line string at ", At(start))});
    return Status::OK();
  }

  // '(' ring {',' ring} ')': the exterior ring, then holes inside it.
  Status ReadPolygon(const Token& tag) {
    Status s = Expect(TokenKind::kOpen, Cat("'(' after ", tag.word));
    const size_t exterior = out_->rings.size();
    for (size_t ring = 0; s.ok(); ++ring) {
      const Token start = tokens_.Peek();
      Coordinates c;
      s = ReadCoordinates(tag, &c);
      if (s.ok()) s = CheckRing(start, ring, &c);
      if (s.ok() && ring > 0) s = CheckHoleInside(start, ring, c, exterior);
      if (!s.ok()) return s;
      out_->rings.push_back({std::move(c.points), std::move(c.z),
                             Cat(RingName(ring), " at ", At(start))});
      if (tokens_.Peek().kind != TokenKind::kComma) break;
      tokens_.Take();
    }
    if (!s.ok()) return s;
    return Expect(TokenKind::kClose, "',' or ')' after a ring");
  }

  // A ring is closed (its last point repeats its first, which is dropped:
  // Polyline rings close implicitly) and has at least 3 distinct points.
  static std::string RingName(size_t ring) {
    return ring == 0 ? "the exterior ring" : Cat("interior ring ", ring);
  }

  Status CheckRing(const Token& start, size_t ring, Coordinates* c) const {
    const std::string name = RingName(ring);
    if (c->points.size() < 4) {
      return Error(start, Cat(name, " has ", c->points.size(),
                              " point(s); a ring needs at least 4 (the "
                              "first repeated last)"));
    }
    const Point2& first = c->points.front();
    const Point2& last = c->points.back();
    if (first.x != last.x || first.y != last.y ||
        (!c->z.empty() && c->z.front() != c->z.back())) {
      return Error(start, Cat(name,
                              " is not closed: its last point differs "
                              "from its first"));
    }
    c->points.pop_back();
    if (!c->z.empty()) c->z.pop_back();
    return Status::OK();
  }

  // Every point of a hole is inside or on the polygon's exterior ring
  // (exact predicates); crossings are the triangulation's to report.
  Status CheckHoleInside(const Token& start, size_t ring, const Coordinates& c,
                         size_t exterior) const {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_2> boundary;
    for (const Point2& p : out_->rings[exterior].points) {
      boundary.emplace_back(p.x, p.y);
    }
    for (size_t k = 0; k < c.points.size(); ++k) {
      const K::Point_2 p(c.points[k].x, c.points[k].y);
      if (CGAL::bounded_side_2(boundary.begin(), boundary.end(), p, K()) ==
          CGAL::ON_UNBOUNDED_SIDE) {
        return Error(start, Cat("interior ring ", ring,
                                " (a hole) is not "
                                "inside the exterior ring: its point ",
                                k, " is outside"));
      }
    }
    return Status::OK();
  }

  WktTokens tokens_;
  std::string_view filename_;
  DatasetConstraints* out_;
  // The coordinate dimension of the geometry being read (0: not known yet).
  int dimension_ = 0;
  static constexpr int kMaxDepth = 16;
  int depth_ = 0;
};

}  // namespace

StatusOr<DatasetConstraints> ParseWktConstraints(std::string_view text,
                                                 std::string_view filename) {
  DatasetConstraints constraints;
  RETURN_IF_ERROR(WktReader(text, filename, &constraints).ReadAll());
  return constraints;
}

bool SplitWktConstraintsSpec(std::string_view spec, std::string_view* points,
                             std::string_view* wkt) {
  const size_t plus = spec.rfind('+');
  if (plus == std::string_view::npos || plus == 0 || !spec.ends_with(".wkt") ||
      spec.size() - plus - 1 <= 4) {
    return false;
  }
  *points = spec.substr(0, plus);
  *wkt = spec.substr(plus + 1);
  return true;
}

}  // namespace locator
