#include "tests/common/gis/hostile_crs.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "common/gis/proj_file_guard.h"
#include "tests/testing/wait.h"

namespace locator::gis::testing {
namespace {

std::string LonLatWithGrid(const std::string& grid) {
  return "+proj=longlat +ellps=WGS84 +nadgrids=" + grid;
}

// `proj`, naming `grid`, as GDAL writes it in `format` ("WKT2_2019",
// "WKT1_GDAL" or "PROJJSON"). GDAL opens the grids a CRS names as it reads
// it, so it is given a grid that exists nowhere, whose name is then
// replaced by `grid`.
std::string Exported(const std::string& proj, const std::string& grid,
                     const std::string& format) {
  constexpr std::string_view kNowhere = "no_such_grid_anywhere.gsb";
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);  // "grid not found"
  OGRSpatialReference srs;
  const std::string nowhere = proj + std::string(kNowhere) + " +type=crs";
  EXPECT_EQ(srs.SetFromUserInput(nowhere.c_str()), OGRERR_NONE) << nowhere;
  char* text = nullptr;
  if (format == "PROJJSON") {
    EXPECT_EQ(srs.exportToPROJJSON(&text, nullptr), OGRERR_NONE) << proj;
  } else {
    const std::string option = "FORMAT=" + format;
    const char* const options[] = {option.c_str(), nullptr};
    EXPECT_EQ(srs.exportToWkt(&text, options), OGRERR_NONE) << proj;
  }
  std::string out = text == nullptr ? "" : text;
  CPLFree(text);
  EXPECT_NE(out.find(kNowhere), std::string::npos) << out;
  for (size_t at = out.find(kNowhere); at != std::string::npos;
       at = out.find(kNowhere, at + grid.size())) {
    out.replace(at, kNowhere.size(), grid);
  }
  return out;
}

}  // namespace

FifoWatch::FifoWatch(std::string path) : path_(std::move(path)) {
  EXPECT_EQ(::mkfifo(path_.c_str(), 0600), 0) << path_;
  watcher_ = std::thread([this] {
    while (!stop_.load()) {
      const int fd = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
      if (fd >= 0) {  // a reader has it open (or is blocked opening it)
        opened_.store(true);
        ::close(fd);
      }
      std::this_thread::sleep_for(test::kWaitPoll);
    }
  });
}

FifoWatch::~FifoWatch() {
  stop_.store(true);
  watcher_.join();
  ::unlink(path_.c_str());
}

std::vector<HostileCrs> HostileCrss(const std::string& fifo,
                                    const std::string& outside_file,
                                    size_t too_long) {
  std::vector<HostileCrs> rows;
  for (const std::string& file :
       {std::string("/dev/ptmx"), fifo, std::string("/dev/zero"),
        std::string("/proc/self/environ"), outside_file}) {
    rows.push_back({"+nadgrids=" + file, LonLatWithGrid(file), file});
  }
  rows.push_back({"a grid list", LonLatWithGrid("@null,@" + fifo), fifo});
  rows.push_back({"a path that climbs out of the data directory",
                  LonLatWithGrid("x/../../../../../../../../../dev/ptmx"),
                  "x/../../../../../../../../../dev/ptmx"});
  rows.push_back(
      {"+geoidgrids", "+proj=longlat +datum=WGS84 +geoidgrids=" + fifo, fifo});
  rows.push_back({"+init of a FIFO", "+init=" + fifo + ":crs", fifo});
  rows.push_back({"+init of a regular file", "+init=" + outside_file + ":crs",
                  outside_file});
  rows.push_back(
      {"+init of /proc", "+init=/proc/self/environ:crs", "/proc/self/environ"});
  for (const std::string format : {"WKT2_2019", "WKT1_GDAL", "PROJJSON"}) {
    for (const std::string& file : {fifo, std::string("/dev/ptmx")}) {
      rows.push_back({format + " naming " + file,
                      Exported(LonLatWithGrid(""), file, format), file});
    }
  }
  rows.push_back(
      {"WKT2 of a geoid grid",
       Exported("+proj=longlat +datum=WGS84 +geoidgrids=", fifo, "WKT2_2019"),
       fifo});
  std::string long_crs = LonLatWithGrid("");
  long_crs.resize(too_long, 'a');
  rows.push_back(
      {"a CRS of " + std::to_string(too_long) + " bytes", long_crs, ""});
  return rows;
}

std::string CopyOfBeta2007Grid(const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string copy = dir + "/BETA2007.gsb";
  for (const std::string& data_dir : ProjDataDirectories()) {
    std::error_code error;
    if (fs::copy_file(data_dir + "/BETA2007.gsb", copy, error)) return copy;
  }
  ADD_FAILURE() << "no BETA2007.gsb (package proj-data) in PROJ's data "
                   "directories";
  return copy;
}

}  // namespace locator::gis::testing
