// Hostile request CRSs, made at test time: CRSs that name a device, a FIFO,
// a /proc file or a regular file outside PROJ's data directories, in every
// form PROJ reads (PROJ strings with +nadgrids, +geoidgrids and +init, WKT2,
// WKT1 with a PROJ4_GRIDS extension, PROJJSON), and one past the length
// limit; and FifoWatch, which tells whether anything opened a FIFO.
//
// Thread-safety: HostileCrss() is a free function; a FifoWatch is owned by
// one test (its thread only touches the FIFO and an atomic).

#ifndef LOCATOR_TESTS_COMMON_GIS_HOSTILE_CRS_H_
#define LOCATOR_TESTS_COMMON_GIS_HOSTILE_CRS_H_

#include <atomic>
#include <string>
#include <thread>
#include <vector>

namespace locator::gis::testing {

// A FIFO at `path`, made on construction, and a thread that keeps trying to
// open it for writing without blocking, which succeeds only while something
// holds it open for reading: then it records that, and (opening and closing
// the writing end) lets that reader go on to end-of-file instead of
// blocking forever. Removed on destruction.
class FifoWatch {
 public:
  explicit FifoWatch(std::string path);
  ~FifoWatch();
  FifoWatch(const FifoWatch&) = delete;
  FifoWatch& operator=(const FifoWatch&) = delete;

  const std::string& path() const { return path_; }
  // Whether anything opened the FIFO for reading so far.
  bool opened() const { return opened_.load(); }

 private:
  const std::string path_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> opened_{false};
  std::thread watcher_;
};

struct HostileCrs {
  std::string what;  // for failure messages
  std::string crs;
  // The file it names, if any: a message about it must quote this.
  std::string file;
};

// The hostile CRSs: each names one of `fifo`, `outside_file` (a regular
// file outside PROJ's data directories), /dev/ptmx, /dev/zero or
// /proc/self/environ, through each of the forms above; and a PROJ string of
// `too_long` bytes.
std::vector<HostileCrs> HostileCrss(const std::string& fifo,
                                    const std::string& outside_file,
                                    size_t too_long);

// A copy of PROJ's grid BETA2007.gsb (Germany, DHDN to ETRS89) at
// DIR/BETA2007.gsb, outside PROJ's data directories; returns its path.
std::string CopyOfBeta2007Grid(const std::string& dir);

}  // namespace locator::gis::testing

#endif  // LOCATOR_TESTS_COMMON_GIS_HOSTILE_CRS_H_
