#include "tests/server/http/browser.h"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

namespace locator::test {
namespace {

std::string HtmlUnescape(std::string text) {
  const std::pair<std::string, std::string> entities[] = {{"&quot;", "\""},
                                                          {"&#39;", "'"},
                                                          {"&lt;", "<"},
                                                          {"&gt;", ">"},
                                                          {"&amp;", "&"}};
  for (const auto& [entity, plain] : entities) {
    for (size_t at = text.find(entity); at != std::string::npos;
         at = text.find(entity, at + plain.size())) {
      text.replace(at, entity.size(), plain);
    }
  }
  return text;
}

}  // namespace

bool ChromiumInstalled() { return access(kChromium, X_OK) == 0; }

std::string ReadFileBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(file)),
                     std::istreambuf_iterator<char>());
}

// Runs headless Chromium on `url` with `flags`; returns its stdout. Its
// stderr goes to a file next to the fresh profile directory. A run that
// `timeout` ends (exit 124: headless Chromium's virtual time budget now and
// then never expires: a run of this test hit the 120 s once) is run once more
// with a fresh profile; a second hang fails the test.
std::string RunChromium(const std::string& url,
                        const std::vector<std::string>& flags) {
  constexpr int kTimedOut = 124;  // timeout(1)'s exit status
  std::string out;
  for (int attempt = 0; attempt < 2; ++attempt) {
    std::string dir_template = ::testing::TempDir() + "chromium-XXXXXX";
    EXPECT_NE(mkdtemp(dir_template.data()), nullptr);
    std::string command = std::string("timeout 120 ") + kChromium +
                          " --headless --no-sandbox --disable-gpu"
                          " --disable-quic --no-first-run"
                          " --disable-background-networking"
                          " --disable-component-update --disable-sync"
                          " --virtual-time-budget=6000"
                          " --user-data-dir=" +
                          dir_template + "/profile";
    for (const std::string& flag : flags) command += " " + flag;
    command += " " + url + " 2>" + dir_template + "/stderr.txt";
    out.clear();
    FILE* pipe = popen(command.c_str(), "r");
    EXPECT_NE(pipe, nullptr) << command;
    if (pipe == nullptr) return out;
    char chunk[4096];
    size_t got;
    while ((got = fread(chunk, 1, sizeof(chunk), pipe)) > 0)
      out.append(chunk, got);
    const int exit_status = pclose(pipe);
    const std::string stderr_text = ReadFileBytes(dir_template + "/stderr.txt");
    std::filesystem::remove_all(dir_template);
    const bool hung =
        WIFEXITED(exit_status) && WEXITSTATUS(exit_status) == kTimedOut;
    if (hung && attempt == 0) {
      std::cerr << "headless Chromium hung on " << url << "; once more\n";
      continue;
    }
    EXPECT_EQ(exit_status, 0) << command << "\n" << stderr_text;
    break;
  }
  return out;
}

// The start tag of the element with id `id` in `dom` ("" if none).
std::string StartTag(const std::string& dom, const std::string& id) {
  const size_t at = dom.find(" id=\"" + id + "\"");
  if (at == std::string::npos) return "";
  const size_t begin = dom.rfind('<', at);
  return dom.substr(begin, dom.find('>', at) - begin + 1);
}

// Attribute `name` of a start tag, unescaped ("" if absent).
std::string Attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size();
  return HtmlUnescape(tag.substr(begin, tag.find('"', begin) - begin));
}

// Width and height from a PNG's IHDR chunk; {0, 0} if it is not a PNG.
std::pair<uint32_t, uint32_t> PngSize(const std::string& png) {
  if (png.size() < 24 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      png.compare(12, 4, "IHDR") != 0) {
    return {0, 0};
  }
  const auto be32 = [&png](size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) {
      v = (v << 8) | static_cast<unsigned char>(png[at + i]);
    }
    return v;
  };
  return {be32(16), be32(20)};
}

void ExpectScreenshotDrawn(const std::string& url, const std::string& png_path,
                           uint32_t width, uint32_t height, size_t min_bytes) {
  std::filesystem::create_directories(
      std::filesystem::path(png_path).parent_path());
  std::filesystem::remove(png_path);
  RunChromium(url, {"--screenshot=" + png_path,
                    "--window-size=" + std::to_string(width) + "," +
                        std::to_string(height)});
  const std::string png = ReadFileBytes(png_path);
  EXPECT_EQ(PngSize(png), std::make_pair(width, height)) << png_path;
  EXPECT_GT(png.size(), min_bytes) << png_path;
}

}  // namespace locator::test
