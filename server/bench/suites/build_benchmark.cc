#include "server/bench/suites/build_benchmark.h"

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/bench/process_status.h"
#include "server/bench/stopwatch.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/mesh_check.h"
#include "server/core/strategies/locator_factory.h"
#include "server/core/tiling/canonical_delaunay.h"
#include "server/core/tiling/tiled_build.h"

namespace locator::bench {

namespace {

// One build: the mesh from the points, then the serving strategy on it.
struct Sample {
  size_t n = 0;
  std::string builder;  // "cgal" or "tiled-<threads>t"
  int repeat = 0;
  double wall_s = 0;  // points to serving mesh (CGAL's triangulation freed)
  double cpu_s = 0;   // user + system, all threads
  TiledBuildStats phases;
  double setup_s = 0;   // MakePointLocator("self-tuning") on the mesh
  double engine_s = 0;  // Engine::Create, the whole published path (tiled)
  double peak_bytes_per_point = 0;
  double check_s = -1;  // CountNonCanonicalEdges, with --verify
  std::shared_ptr<const ServingMesh> mesh;
};

double CpuSeconds() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) +
           static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Returns freed memory to the system and restarts the kernel's peak
// resident set mark (clear_refs 5); the resident set now.
size_t StartPeak() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return ProcessStatusBytes("VmRSS:");
}

Status SetUpStrategy(const ServingMesh& mesh, Sample* sample) {
  const Stopwatch watch;
  const StatusOr<std::unique_ptr<PointLocator>> locator =
      MakePointLocator("self-tuning", mesh, TuningOptions());
  sample->setup_s = watch.Seconds();
  return locator.status();
}

Status BuildWithCgal(const Dataset& dataset, Sample* sample) {
  const size_t before = StartPeak();
  const double cpu = CpuSeconds();
  const Stopwatch watch;
  ASSIGN_OR_RETURN(std::unique_ptr<Triangulation> t,
                   Triangulation::Build(dataset));
  sample->mesh = t->shared_mesh();
  t.reset();  // as the engine does: it serves from the mesh alone
  sample->wall_s = watch.Seconds();
  sample->cpu_s = CpuSeconds() - cpu;
  sample->peak_bytes_per_point = double(ProcessStatusBytes("VmHWM:") - before) /
                                 double(dataset.points.size());
  return SetUpStrategy(*sample->mesh, sample);
}

Status BuildInTiles(const Dataset& dataset, unsigned threads, Sample* sample) {
  size_t before = StartPeak();
  double cpu = CpuSeconds();
  Stopwatch watch;
  TiledBuildOptions options;
  options.threads = threads;
  BuiltMesh built;
  RETURN_IF_ERROR(BuildTiledMesh(dataset.points, dataset.values, options,
                                 &built, &sample->phases));
  sample->wall_s = watch.Seconds();
  sample->cpu_s = CpuSeconds() - cpu;
  sample->peak_bytes_per_point = double(ProcessStatusBytes("VmHWM:") - before) /
                                 double(dataset.points.size());
  sample->mesh = built.mesh;
  RETURN_IF_ERROR(SetUpStrategy(*sample->mesh, sample));
  // The published path: what locatord does with these points.
  Dataset copy = dataset;
  EngineOptions engine_options;
  engine_options.build_threads = threads;
  watch.Restart();
  const StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(std::move(copy), engine_options);
  sample->engine_s = watch.Seconds();
  return engine.status();
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

std::string Fixed(double v, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.*f", digits, v);
  return text;
}

void PrintSamples(const std::vector<Sample>& samples, bool csv,
                  std::ostream& out) {
  const std::vector<std::string> header = {
      "n",       "builder",     "repeat",     "wall_s",
      "cpu_s",   "sort_s",      "tiles_s",    "assembly_s",
      "setup_s", "ready_s",     "engine_s",   "peak_B_per_point",
      "tiles",   "halo_points", "max_rounds", "canonical_check_s"};
  const auto row = [&](const std::vector<std::string>& cells) {
    for (size_t k = 0; k < cells.size(); ++k) {
      out << (csv ? (k ? "," : "") : "| ") << cells[k] << (csv ? "" : " ");
    }
    out << (csv ? "\n" : "|\n");
  };
  row(header);
  if (!csv) row(std::vector<std::string>(header.size(), "---"));
  for (const Sample& s : samples) {
    const bool tiled = s.builder != "cgal";
    row({std::to_string(s.n), s.builder, std::to_string(s.repeat),
         Fixed(s.wall_s), Fixed(s.cpu_s),
         tiled ? Fixed(s.phases.sort_seconds) : "-",
         tiled ? Fixed(s.phases.tiles_seconds) : "-",
         tiled ? Fixed(s.phases.assembly_seconds) : "-", Fixed(s.setup_s),
         Fixed(s.wall_s + s.setup_s), tiled ? Fixed(s.engine_s) : "-",
         Fixed(s.peak_bytes_per_point, 0),
         tiled ? std::to_string(s.phases.tiles) : "-",
         tiled ? std::to_string(s.phases.halo_points) : "-",
         tiled ? std::to_string(s.phases.max_rounds) : "-",
         s.check_s >= 0 ? Fixed(s.check_s) : "-"});
  }
}

// Medians per builder, and the ratios of the builds of each repeat.
void PrintSummary(const std::vector<Sample>& samples, size_t n,
                  const std::vector<std::string>& builders, std::ostream& out) {
  out << "\nn = " << n << ": medians over repeats\n";
  std::map<std::string, std::vector<const Sample*>> by_builder;
  for (const Sample& s : samples) {
    if (s.n == n) by_builder[s.builder].push_back(&s);
  }
  for (const std::string& builder : builders) {
    std::vector<double> wall, cpu, ready, engine, peak;
    for (const Sample* s : by_builder[builder]) {
      wall.push_back(s->wall_s);
      cpu.push_back(s->cpu_s);
      ready.push_back(s->wall_s + s->setup_s);
      engine.push_back(s->engine_s);
      peak.push_back(s->peak_bytes_per_point);
    }
    out << "  " << builder << ": wall " << Fixed(Median(wall)) << " s, cpu "
        << Fixed(Median(cpu)) << " s, ready " << Fixed(Median(ready)) << " s"
        << (builder == "cgal"
                ? ""
                : ", Engine::Create " + Fixed(Median(engine)) + " s")
        << ", peak " << Fixed(Median(peak), 0) << " B/point\n";
  }
  // Ratios of wall seconds within each repeat, then their median.
  const auto ratio = [&](const std::string& a, const std::string& b) {
    std::vector<double> r;
    const auto& x = by_builder[a];
    const auto& y = by_builder[b];
    for (size_t k = 0; k < std::min(x.size(), y.size()); ++k) {
      r.push_back(x[k]->wall_s / y[k]->wall_s);
    }
    return Median(r);
  };
  for (size_t k = 1; k < builders.size(); ++k) {
    out << "  wall " << builders[0] << " / " << builders[k] << ": "
        << Fixed(ratio(builders[0], builders[k]), 2) << "\n";
  }
  for (size_t k = 2; k < builders.size(); ++k) {
    out << "  wall " << builders[1] << " / " << builders[k] << ": "
        << Fixed(ratio(builders[1], builders[k]), 2) << "\n";
  }
}

}  // namespace

Status RunBuild(const BuildOptions& options, std::ostream& out) {
  std::vector<Sample> samples;
  std::vector<std::string> builders = {"cgal"};
  for (const unsigned t : options.threads) {
    builders.push_back("tiled-" + std::to_string(t) + "t");
  }
  for (const size_t n : options.sizes) {
    const Dataset dataset = GenerateUniform(n, 1);
    for (int repeat = 0; repeat < options.repeats; ++repeat) {
      std::vector<Sample> round(builders.size());
      // Alternate: each repeat starts with the next builder.
      for (size_t step = 0; step < builders.size(); ++step) {
        const size_t b = (step + repeat) % builders.size();
        Sample& s = round[b];
        s.n = n;
        s.builder = builders[b];
        s.repeat = repeat;
        const Status status =
            b == 0 ? BuildWithCgal(dataset, &s)
                   : BuildInTiles(dataset, options.threads[b - 1], &s);
        if (!status.ok()) return status;
        if (!options.verify) s.mesh.reset();
      }
      if (options.verify) {
        for (size_t b = 1; b < builders.size(); ++b) {
          RETURN_IF_ERROR(CompareMeshArrays(round[b].mesh->arrays(),
                                            round[0].mesh->arrays()));
          const Stopwatch watch;
          const size_t bad = CountNonCanonicalEdges(*round[b].mesh);
          round[b].check_s = watch.Seconds();
          if (bad != 0) {
            return Status::Internal(std::to_string(bad) +
                                    " non-canonical edges in the tiled mesh");
          }
        }
      }
      for (Sample& s : round) {
        s.mesh.reset();
        samples.push_back(std::move(s));
      }
    }
  }
  PrintSamples(samples, options.csv, out);
  for (const size_t n : options.sizes) PrintSummary(samples, n, builders, out);
  return Status::OK();
}

}  // namespace locator::bench
