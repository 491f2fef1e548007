#include "client/load/svg_writer.h"

#include <cstdio>

#include "common/str_cat.h"

namespace locator {
namespace {

// Coordinates to 0.01 user units: plenty for a chart, and short.
std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", value);
  return text;
}

std::string Attribute(std::string_view name, std::string_view value) {
  return StrCat({" ", name, "=\"", XmlEscape(value), "\""});
}

std::string Attribute(std::string_view name, double value) {
  return Attribute(name, Number(value));
}

}  // namespace

std::string XmlEscape(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        escaped.append("&amp;");
        break;
      case '<':
        escaped.append("&lt;");
        break;
      case '>':
        escaped.append("&gt;");
        break;
      case '"':
        escaped.append("&quot;");
        break;
      case '\'':
        escaped.append("&apos;");
        break;
      default:
        escaped.push_back(c);
    }
  }
  return escaped;
}

SvgWriter::SvgWriter(double width, double height)
    : width_(width), height_(height) {}

void SvgWriter::Element(std::string_view name, const std::string& attributes,
                        std::string_view style) {
  body_.append(
      StrCat({"<", name, attributes, Attribute("style", style), "/>\n"}));
}

void SvgWriter::TextElement(const std::string& attributes,
                            std::string_view text, std::string_view style) {
  body_.append(StrCat({"<text", attributes, Attribute("style", style), ">",
                       XmlEscape(text), "</text>\n"}));
}

void SvgWriter::Rect(double x, double y, double width, double height,
                     std::string_view style) {
  Element("rect",
          StrCat({Attribute("x", x), Attribute("y", y),
                  Attribute("width", width), Attribute("height", height)}),
          style);
}

void SvgWriter::Line(SvgPoint from, SvgPoint to, std::string_view style) {
  Element("line",
          StrCat({Attribute("x1", from.x), Attribute("y1", from.y),
                  Attribute("x2", to.x), Attribute("y2", to.y)}),
          style);
}

void SvgWriter::Polyline(std::span<const SvgPoint> points,
                         std::string_view style) {
  std::string list;
  for (const SvgPoint& point : points) {
    if (!list.empty()) list.push_back(' ');
    list.append(StrCat({Number(point.x), ",", Number(point.y)}));
  }
  Element("polyline", Attribute("points", list), style);
}

void SvgWriter::Text(SvgPoint at, std::string_view text,
                     std::string_view style) {
  TextElement(StrCat({Attribute("x", at.x), Attribute("y", at.y)}), text,
              style);
}

void SvgWriter::VerticalText(SvgPoint at, std::string_view text,
                             std::string_view style) {
  const std::string rotate =
      StrCat({"rotate(-90 ", Number(at.x), " ", Number(at.y), ")"});
  TextElement(StrCat({Attribute("x", at.x), Attribute("y", at.y),
                      Attribute("transform", rotate)}),
              text, style);
}

std::string SvgWriter::Finish() const {
  return StrCat({"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n",
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"",
                 Attribute("width", width_), Attribute("height", height_),
                 Attribute("viewBox", StrCat({"0 0 ", Number(width_), " ",
                                              Number(height_)})),
                 ">\n", body_, "</svg>\n"});
}

}  // namespace locator
