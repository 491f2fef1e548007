// CheckSvg: judges an SVG document with a real XML parser, by running
// tests/client/svg_check.py (python3's xml.etree) on it, and returns its
// summary for the test to check.
//
// Thread-safety: a free function; each call has its own file.

#ifndef LOCATOR_TESTS_CLIENT_SVG_CHECK_H_
#define LOCATOR_TESTS_CLIENT_SVG_CHECK_H_

#include <string>
#include <vector>

namespace locator::test {

struct SvgSummary {
  bool well_formed = false;
  std::string error;  // the parser's message when not well formed
  std::string root;   // "svg"
  std::vector<int> polyline_points;  // points of each polyline, in order
  int dashed_lines = 0;
  std::vector<std::string> texts;  // text element contents, unescaped
};

// The summary of the SVG file at `path`.
SvgSummary CheckSvgFile(const std::string& path);
// The same for a document in memory.
SvgSummary CheckSvgText(const std::string& svg);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_CLIENT_SVG_CHECK_H_
