// Headless Chromium for the browser tests (Debian's chromium; the tests
// skip without it), and reading what it leaves: the DOM it dumps and the
// screenshots it takes.
//
// Thread-safety: free functions; each run of Chromium has a fresh profile.

#ifndef LOCATOR_TESTS_SERVER_HTTP_BROWSER_H_
#define LOCATOR_TESTS_SERVER_HTTP_BROWSER_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace locator::test {

inline constexpr char kChromium[] = "/usr/bin/chromium";

// Whether kChromium can be run.
bool ChromiumInstalled();

// Runs headless Chromium on `url` with `flags` (e.g. "--dump-dom"), with 6 s
// of virtual time for the page's scripts; returns its stdout. A failed run
// is a test failure.
std::string RunChromium(const std::string& url,
                        const std::vector<std::string>& flags);

// The start tag of the element with id `id` in `dom` ("" if none).
std::string StartTag(const std::string& dom, const std::string& id);

// Attribute `name` of a start tag, unescaped ("" if absent).
std::string Attribute(const std::string& tag, const std::string& name);

// Width and height from a PNG's IHDR chunk; {0, 0} if it is not a PNG.
std::pair<uint32_t, uint32_t> PngSize(const std::string& png);

// The bytes of the file at `path` ("" if it cannot be read).
std::string ReadFileBytes(const std::string& path);

// Takes a width x height screenshot of `url` into `png_path` (creating its
// directory) and checks that it is a PNG of that size larger than
// `min_bytes`: a blank page compresses to a few KB, a drawn one does not.
void ExpectScreenshotDrawn(const std::string& url, const std::string& png_path,
                           uint32_t width, uint32_t height, size_t min_bytes);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_BROWSER_H_
