#include "tests/client/svg_check.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "tests/testing/run_binary.h"

namespace locator::test {

SvgSummary CheckSvgFile(const std::string& path) {
  SvgSummary summary;
  const BinaryResult result = RunBinary(PYTHON3_PATH, {SVG_CHECK_PY, path});
  if (result.exit_code != 0) {
    summary.error = result.err;
    return summary;
  }
  google::protobuf::Struct parsed;
  if (!google::protobuf::util::JsonStringToMessage(result.out, &parsed).ok()) {
    summary.error = "svg_check.py printed no JSON: " + result.out;
    return summary;
  }
  summary.well_formed = true;
  const auto& fields = parsed.fields();
  summary.root = fields.at("root").string_value();
  for (const auto& count : fields.at("polylines").list_value().values()) {
    summary.polyline_points.push_back(static_cast<int>(count.number_value()));
  }
  summary.dashed_lines =
      static_cast<int>(fields.at("dashed_lines").number_value());
  for (const auto& text : fields.at("texts").list_value().values()) {
    summary.texts.push_back(text.string_value());
  }
  return summary;
}

SvgSummary CheckSvgText(const std::string& svg) {
  std::string path = ::testing::TempDir() + "svg_check_XXXXXX";
  const int fd = mkstemp(path.data());
  if (fd >= 0) close(fd);
  std::ofstream(path) << svg;
  SvgSummary summary = CheckSvgFile(path);
  unlink(path.c_str());
  return summary;
}

}  // namespace locator::test
