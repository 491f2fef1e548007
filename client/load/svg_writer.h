// SvgWriter: builds a small SVG 1.1 document in memory from lines,
// polylines, rectangles and text, for charts a program writes without any
// plotting toolchain.
//
// Every element carries a CSS `style` attribute; text content and
// attribute values are XML-escaped, so any string (a file path, a target
// with '&' or '<') yields a well-formed document. Coordinates are in user
// units, origin at the top left, y growing downwards.
//
// Owns the document text. Thread-safety: none; one thread builds it.

#ifndef LOCATOR_CLIENT_LOAD_SVG_WRITER_H_
#define LOCATOR_CLIENT_LOAD_SVG_WRITER_H_

#include <span>
#include <string>
#include <string_view>

namespace locator {

struct SvgPoint {
  double x = 0;
  double y = 0;
};

// `text` with &, <, >, " and ' replaced by their XML entities.
std::string XmlEscape(std::string_view text);

class SvgWriter {
 public:
  // A `width` x `height` document.
  SvgWriter(double width, double height);

  void Rect(double x, double y, double width, double height,
            std::string_view style);
  void Line(SvgPoint from, SvgPoint to, std::string_view style);
  // One polyline through `points`; an empty span still adds the element.
  void Polyline(std::span<const SvgPoint> points, std::string_view style);
  // `text` with its baseline starting at (x, y) (or centred / ending there
  // with a `text-anchor` in `style`).
  void Text(SvgPoint at, std::string_view text, std::string_view style);
  // The same, rotated 90 degrees counter-clockwise about `at` (a vertical
  // axis title).
  void VerticalText(SvgPoint at, std::string_view text, std::string_view style);

  // The complete document, with the XML declaration.
  std::string Finish() const;

 private:
  // Appends the empty element `<name attributes style="..."/>`.
  void Element(std::string_view name, const std::string& attributes,
               std::string_view style);
  // Appends `<text attributes style="...">text</text>`.
  void TextElement(const std::string& attributes, std::string_view text,
                   std::string_view style);

  const double width_;
  const double height_;
  std::string body_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_SVG_WRITER_H_
