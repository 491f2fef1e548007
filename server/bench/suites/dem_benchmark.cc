#include "server/bench/suites/dem_benchmark.h"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <string>

#include "common/elevation_grid.h"
#include "locator/dataset.h"
#include "server/bench/stopwatch.h"
#include "server/core/terrain/fractal_terrain.h"
#include "server/core/terrain/grid/triangulate_grid.h"
#include "server/core/terrain/points/reference_greedy.h"

namespace locator::bench {
namespace {

// What one build in a child process reports back through a pipe.
struct BuildResult {
  bool ok = false;
  double seconds = 0;
  double cpu_seconds = 0;  // user + system, of the build's process
  uint64_t vertices = 0;
  uint64_t triangles = 0;
  double certified = 0;
  uint64_t peak_kb = 0;  // VmHWM
  char error[200] = {};
};

double CpuSeconds() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) +
           1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

uint64_t PeakKb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6));
  }
  return 0;
}

// What a child runs.
enum class Build { kOneThread, kTwoThreads, kReference };

BuildResult RunBuild(const ElevationGrid& grid, double max_error, Build build) {
  BuildResult result;
  Stopwatch watch;
  const double cpu_before = CpuSeconds();
  Status s;
  if (build == Build::kReference) {
    ReferenceTin tin;
    s = ReferenceGreedyGrid(grid, max_error, 0, &tin);
    result.vertices = tin.vertices;
    result.triangles = tin.triangles.size();
    result.certified = tin.max_error;
  } else {
    TinOptions options;
    options.max_error = max_error;
    options.threads = build == Build::kOneThread ? 1 : 2;
    Dataset tin;
    SimplificationStats stats;
    s = TriangulateGrid(grid, options, &tin, &stats);
    result.vertices = stats.vertices;
    result.triangles = stats.triangles;
    result.certified = stats.max_error;
  }
  result.seconds = watch.Seconds();
  result.cpu_seconds = CpuSeconds() - cpu_before;
  result.ok = s.ok();
  std::snprintf(result.error, sizeof(result.error), "%s", s.ToString().c_str());
  result.peak_kb = PeakKb();
  return result;
}

// Runs one build in a child process.
BuildResult InChild(const ElevationGrid& grid, double max_error, Build build) {
  BuildResult result;
  int fds[2];
  if (pipe(fds) != 0) {
    std::snprintf(result.error, sizeof(result.error), "pipe: %s",
                  std::strerror(errno));
    return result;
  }
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const BuildResult r = RunBuild(grid, max_error, build);
    const ssize_t written = write(fds[1], &r, sizeof(r));
    _exit(written == sizeof(r) ? 0 : 1);
  }
  close(fds[1]);
  if (pid < 0) {
    close(fds[0]);
    std::snprintf(result.error, sizeof(result.error), "fork: %s",
                  std::strerror(errno));
    return result;
  }
  const ssize_t got = read(fds[0], &result, sizeof(result));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (got != sizeof(result)) {
    result = BuildResult();
    std::snprintf(result.error, sizeof(result.error),
                  "the build's process ended without a result (status %d)",
                  status);
  }
  return result;
}

double HeightRange(const ElevationGrid& grid) {
  const auto [lo, hi] =
      std::minmax_element(grid.values.begin(), grid.values.end());
  return *hi - *lo;
}

}  // namespace

Status RunDemBenchmark(const DemBenchOptions& options, std::ostream& out) {
  out << "# TriangulateGrid on fractal DEMs (FractalTerrain, seed "
      << options.seed << "); e is a fraction of the height range.\n"
      << "# seconds: best of " << options.repeats
      << " (1 and 2 threads alternating); peak: the build process's VmHWM "
         "(the DEM included).\n"
      << "# hmm's README (2018 MacBook Pro, 1 thread, Everest DEM): e=0.001 "
         "5.6 MP 935,787 triangles in 2.35 s; 90 MP 1,084,972 in 13.1 s.\n";
  out << std::left << std::setw(7) << "size" << std::right << std::setw(8)
      << "e" << std::setw(10) << "1 thr s" << std::setw(10) << "2 thr s"
      << std::setw(7) << "ratio" << std::setw(9) << "1t cpu" << std::setw(9)
      << "2t cpu" << std::setw(11) << "triangles" << std::setw(10) << "vertices"
      << std::setw(10) << "ref vert" << std::setw(8) << "vs ref" << std::setw(9)
      << "1t MB" << std::setw(9) << "2t MB" << std::setw(10) << "cert/E"
      << "\n";
  for (const uint32_t size : options.sizes) {
    FractalTerrainOptions terrain;
    terrain.seed = options.seed;
    const ElevationGrid grid = FractalTerrain(size, size, terrain, 2);
    const double range = HeightRange(grid);
    for (const double e : options.errors) {
      const double max_error = e * range;
      BuildResult one, two;
      one.seconds = two.seconds = std::numeric_limits<double>::infinity();
      for (int k = 0; k < options.repeats; ++k) {
        const BuildResult a = InChild(grid, max_error, Build::kOneThread);
        const BuildResult b = InChild(grid, max_error, Build::kTwoThreads);
        if (!a.ok || !b.ok) {
          return Status::Internal(std::string("size ") + std::to_string(size) +
                                  ": " + (a.ok ? b.error : a.error));
        }
        if (a.seconds < one.seconds) one = a;
        if (b.seconds < two.seconds) two = b;
      }
      BuildResult reference;
      if (options.reference) {
        reference = InChild(grid, max_error, Build::kReference);
        if (!reference.ok) return Status::Internal(reference.error);
      }
      out << std::left << std::setw(7) << size << std::right << std::setw(8)
          << e << std::fixed << std::setprecision(3) << std::setw(10)
          << one.seconds << std::setw(10) << two.seconds << std::setprecision(2)
          << std::setw(7) << one.seconds / two.seconds << std::setprecision(3)
          << std::setw(9) << one.cpu_seconds << std::setw(9) << two.cpu_seconds
          << std::setw(11) << two.triangles << std::setw(10) << two.vertices
          << std::setw(10) << reference.vertices << std::setprecision(1)
          << std::setw(7)
          << (options.reference ? 100.0 * (static_cast<double>(two.vertices) /
                                               reference.vertices -
                                           1)
                                : 0.0)
          << "%" << std::setprecision(0) << std::setw(9) << one.peak_kb / 1024.0
          << std::setw(9) << two.peak_kb / 1024.0 << std::setprecision(4)
          << std::setw(10) << two.certified / max_error << "\n"
          << std::defaultfloat << std::flush;
    }
  }
  return Status::OK();
}

}  // namespace locator::bench
